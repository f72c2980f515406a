// The first-ripple reach of every design this program has simulated, kept by
// design (the scene without what is only drawn), so that a design map opened
// again, a map over a clicked cell's neighbours, and the ladder editor's live
// estimate reuse a run instead of repeating it. Used from the UI thread only.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/design/ripple_reach.h"

#include <QByteArray>
#include <QHash>

#include <optional>

namespace jl::ui {

class ReachCache {
public:
    // The one cache of the program (the map and the editor share it).
    static ReachCache& shared();

    // What identifies a design: the scene file text of the scene with its
    // title, description, colours, ribbons and view left out (they change
    // nothing in the run), hashed.
    static QByteArray designKey(const jl::Scene& scene);

    std::optional<jl::RippleReach> find(const QByteArray& key) const;
    // A cancelled run is not a result and is not kept.
    void keep(const QByteArray& key, const jl::RippleReach& reach);
    int size() const { return int(reaches_.size()); }

private:
    QHash<QByteArray, jl::RippleReach> reaches_;
};

}  // namespace jl::ui
