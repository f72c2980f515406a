#include "ui/view3d/round_length.h"

#include <QObject>

#include <cmath>

namespace jl::ui {

double gridCell(double pixelsPerMetre, double leastPixels) {
    // 1e6 m (a thousand kilometres) ends the search for a degenerate scale.
    for (double decade = 0.01; decade < 1e6; decade *= 10)
        for (const double mantissa : {1.0, 2.0, 5.0})
            if (mantissa * decade * pixelsPerMetre >= leastPixels) return mantissa * decade;
    return 1e6;
}

QString lengthText(double metres) {
    if (metres < 1) return QObject::tr("%1 cm").arg(std::lround(metres * 100));
    if (metres < 1000) return QObject::tr("%1 m").arg(std::lround(metres));
    return QObject::tr("%1 km").arg(metres / 1000);
}

}  // namespace jl::ui
