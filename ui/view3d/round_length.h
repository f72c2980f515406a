// Round lengths for the side view's grid and the 3-D view's scale bar.
#pragma once

#include <QString>

namespace jl::ui {

// The grid's cell: the shortest round length (1, 2 or 5 times a power of
// ten, from 1 cm up, without an upper end: a ladder of 100,000 blocks is
// 6 km tall) that is at least `leastPixels` long at `pixelsPerMetre`; and
// that length in words for a scale bar (cm, m or km).
double gridCell(double pixelsPerMetre, double leastPixels);
QString lengthText(double metres);

}  // namespace jl::ui
