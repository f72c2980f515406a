// The virtual lab the ladder hangs in: floor, walls and a table under the
// ladder, sized to the ladder so long ladders still fit.
#pragma once

#include <Qt3DCore/QEntity>

namespace Qt3DCore {
class QTransform;
}

namespace jl::ui {

class Room : public Qt3DCore::QEntity {
public:
    explicit Room(Qt3DCore::QNode* parent);
    // `extent`: how far below the origin the ladder reaches (m).
    void fitTo(double extent);

private:
    Qt3DCore::QTransform* transform_;
};

}  // namespace jl::ui
