// The virtual lab the ladder hangs in: floor, walls and a table under the
// ladder, sized to the ladder so long ladders still fit.
#pragma once

#include <Qt3DCore/QEntity>

#include <optional>

namespace Qt3DCore {
class QTransform;
}

namespace jl::ui {

class Room : public Qt3DCore::QEntity {
public:
    explicit Room(Qt3DCore::QNode* parent);
    // `extent`: how far below the origin the ladder reaches (m). `tableTop`:
    // the scene's floor (m), where the table's top then is; left out, the
    // table stands a little below the ladder.
    void fitTo(double extent, std::optional<double> tableTop = std::nullopt);

private:
    Qt3DCore::QTransform* transform_;
};

}  // namespace jl::ui
