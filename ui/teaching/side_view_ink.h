// The ink of the side view's words and lines, shared by the files that
// paint it.
#pragma once

#include <QColor>

namespace jl::ui {

inline const QColor kSideInk(40, 40, 46);

}  // namespace jl::ui
