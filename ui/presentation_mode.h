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
    // `keepDocks`: the docks that stay in view (the rest hide); `play`: what
    // Space does while presenting, wherever the keyboard is.
    PresentationMode(QMainWindow* window, QList<QDockWidget*> keepDocks, QAction* play);

    bool active() const { return active_; }
    void setActive(bool on);
    void toggle() { setActive(!active_); }
    // Fonts in presentation mode are this many times the normal size on a
    // screen 900 pixels high (times presentationSize elsewhere).
    static constexpr double kFontScale = 1.6;

signals:
    // Views and plots connect here to draw large (SideView scale, RunPlots::setLarge).
    void activeChanged(bool on);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void enter();
    void leave();

    QMainWindow* window_;
    QList<QDockWidget*> keepDocks_;
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
