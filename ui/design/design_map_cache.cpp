#include "ui/design/design_map_cache.h"

#include "jl/scene/scene_io.h"

#include <QCryptographicHash>

namespace jl::ui {

ReachCache& ReachCache::shared() {
    static ReachCache cache;
    return cache;
}

QByteArray ReachCache::designKey(const jl::Scene& scene) {
    jl::Scene s = scene;
    s.title.clear();
    s.description.clear();
    s.view = {};
    if (s.ladder) {
        s.ladder->block.color = {};
        s.ladder->ribbons = {};
        for (jl::BlockOverride& o : s.ladder->overrides) o.color.reset();
    }
    for (jl::BodySpec& b : s.bodies) b.color = {};
    const std::string text = jl::sceneToYaml(s);
    return QCryptographicHash::hash(QByteArray::fromStdString(text), QCryptographicHash::Sha256);
}

std::optional<jl::RippleReach> ReachCache::find(const QByteArray& key) const {
    const auto it = reaches_.constFind(key);
    if (it == reaches_.constEnd()) return std::nullopt;
    return *it;
}

void ReachCache::keep(const QByteArray& key, const jl::RippleReach& reach) {
    if (!reach.cancelled) reaches_.insert(key, reach);
}

}  // namespace jl::ui
