// Keeps a top-level window within the usable area of its screen: a geometry
// restored from another, larger screen, or a window grown by a layout in
// large type, must not leave the status bar and the plots off the screen.
#pragma once

class QWidget;

namespace jl::ui {

// Shrinks the window to the screen's available area (less the frame the
// window manager adds) and moves it onto it; full screen and maximised
// windows are the window manager's to place.
void fitToScreen(QWidget* window);

}  // namespace jl::ui
