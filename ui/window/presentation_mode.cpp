#include "ui/window/presentation_mode.h"

#include "ui/window/screen_fit.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QKeyEvent>
#include <QMainWindow>
#include <QMenuBar>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>

#include <algorithm>

namespace jl::ui {

PresentationMode::PresentationMode(QMainWindow* window, Docks docks, QAction* play)
    : QObject(window),
      window_(window),
      docks_(docks),
      keepDocks_{docks.sideView, docks.plots, docks.lesson},
      play_(play) {
    escape_ = new QAction(tr("Leave presentation mode"), this);
    escape_->setShortcut(Qt::Key_Escape);
    // The 3-D view is a window of its own inside ours: with the keyboard
    // there, a window shortcut never fires. Presenting owns the screen, so
    // Esc may act application-wide (the action exists only while presenting).
    escape_->setShortcutContext(Qt::ApplicationShortcut);
    connect(escape_, &QAction::triggered, this, [this] { setActive(false); });
}

double presentationSize(const QWidget* w) {
    const QScreen* screen = w ? w->screen() : nullptr;
    const double height = screen ? screen->geometry().height() : 900;
    return std::clamp(height / 900.0, 0.8, 1.0);
}

void PresentationMode::setActive(bool on) {
    if (on == active_) return;
    active_ = on;
    on ? enter() : leave();
    emit activeChanged(on);
}

void PresentationMode::enter() {
    windowState_ = window_->windowState();
    font_ = window_->font();
    QFont big = font_;
    big.setPointSizeF(font_.pointSizeF() * kFontScale * presentationSize(window_));
    window_->setFont(big);
    hidden_.clear();
    QList<QWidget*> chrome{window_->menuBar(), window_->statusBar()};
    for (QToolBar* t : window_->findChildren<QToolBar*>()) chrome << t;
    for (QDockWidget* d : window_->findChildren<QDockWidget*>())
        if (!keepDocks_.contains(d)) chrome << d;
    for (QWidget* w : chrome)
        if (w && w->isVisible()) {
            w->hide();
            hidden_ << w;
        }
    // Shortcuts of actions that lived only in the hidden menus and toolbars
    // die with them: the window itself carries them while presenting.
    lifted_.clear();
    for (QAction* a : window_->findChildren<QAction*>())
        if (!a->shortcuts().isEmpty() && !window_->actions().contains(a)) lifted_ << a;
    window_->addActions(lifted_);
    window_->addAction(escape_);
    // In front of a class Space plays and pauses, even when the keyboard was
    // left in a text field (which would take the space as a character).
    qApp->installEventFilter(this);
    if (QWidget* f = QApplication::focusWidget(); f && window_->isAncestorOf(f)) f->clearFocus();
    window_->showFullScreen();
}

bool PresentationMode::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() != QEvent::ShortcutOverride && event->type() != QEvent::KeyPress)
        return QObject::eventFilter(watched, event);
    const auto* key = static_cast<QKeyEvent*>(event);
    if (key->key() != Qt::Key_Space || key->modifiers() != Qt::NoModifier) return false;
    // Taken before any widget or shortcut sees it: the key press plays, once.
    if (event->type() == QEvent::ShortcutOverride)
        event->accept();
    else if (!key->isAutoRepeat())
        play_->trigger();
    return true;
}

// Large type needs room: on the projector the plots get a third of the
// screen's height (their tick labels would otherwise be cut to "..."), and
// their own height back afterwards.
void PresentationMode::arrangeDocks(bool on) {
    QDockWidget* plots = docks_.plots;
    if (!on) {
        if (plotsHeightBefore_ > 0) window_->resizeDocks({plots}, {plotsHeightBefore_}, Qt::Vertical);
        plotsHeightBefore_ = -1;
        return;
    }
    plotsHeightBefore_ = plots->height();
    QTimer::singleShot(0, this, [this, plots] {
        if (!active()) return;
        window_->resizeDocks({plots}, {std::max(plots->height(), window_->height() / 3)}, Qt::Vertical);
        // The 3-D view is what the class watches: the columns beside it get
        // less than the desk layout gave (the lesson's words more than the
        // side view's thread), and the view half the width.
        window_->resizeDocks({docks_.lesson, docks_.sideView}, {window_->width() * 3 / 10, window_->width() / 5},
                             Qt::Horizontal);
    });
}

void PresentationMode::leave() {
    qApp->removeEventFilter(this);
    window_->removeAction(escape_);
    for (QAction* a : lifted_) window_->removeAction(a);
    lifted_.clear();
    // Normal type before the chrome comes back: the chrome laid out in large
    // type needs more height than the screen has, and a layout grows its
    // window to its minimum but never shrinks it back.
    window_->setFont(font_);
    for (const QPointer<QWidget>& w : hidden_)
        if (w) w->show();
    hidden_.clear();
    window_->setWindowState(windowState_);
    // Once the layout has settled in normal type and the window is back to
    // its normal state, it must be within the screen again.
    QTimer::singleShot(0, window_, [w = window_] { fitToScreen(w); });
}

}  // namespace jl::ui
