// Presentation mode: full screen, large fonts and lines, minimal chrome, the
// keyboard in charge, for a teacher in front of a projector.
#pragma once

#include <QFont>
#include <QList>
#include <QObject>
#include <QPointer>

class QAction;
class QDockWidget;
class QMainWindow;
class QWidget;

namespace jl::ui {

// How large presentation mode draws on `w`'s screen, relative to a screen
// 900 pixels high (0.8 on a 720-pixel projector, 1.2 on a 1080-pixel one):
// large type that fits a small projector would be lost on a large one.
double presentationSize(const QWidget* w);

class PresentationMode : public QObject {
    Q_OBJECT
public:
    // The docks that stay in view while presenting (the rest hide).
    struct Docks {
        QDockWidget* sideView;
        QDockWidget* plots;
        QDockWidget* lesson;
    };
    // `play`: what Space does while presenting, wherever the keyboard is.
    PresentationMode(QMainWindow* window, Docks docks, QAction* play);

    bool active() const { return active_; }
    void setActive(bool on);
    void toggle() { setActive(!active_); }
    // Fonts in presentation mode are this many times the normal size on a
    // screen 900 pixels high (times presentationSize elsewhere).
    static constexpr double kFontScale = 1.6;
    // The docks' sizes on the projector, and back afterwards; the window
    // calls it after the docks have taken their large type.
    void arrangeDocks(bool on);

signals:
    // Views and plots connect here to draw large (SideView scale, RunPlots::setLarge).
    void activeChanged(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void enter();
    void leave();

    QMainWindow* window_;
    Docks docks_;
    QList<QDockWidget*> keepDocks_;
    int plotsHeightBefore_ = -1;  // the plots dock's height before presenting
    bool active_ = false;
    // What entering changed, to put back exactly on leaving.
    Qt::WindowStates windowState_;
    QFont font_;
    QList<QPointer<QWidget>> hidden_;
    QList<QAction*> lifted_;
    QAction* escape_;  // Esc leaves, whatever has the focus
    QAction* play_;    // Space plays or pauses, whatever has the focus
};

}  // namespace jl::ui
