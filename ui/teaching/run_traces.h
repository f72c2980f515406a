// The numbers the plots draw, one sample per frame of the run: energies and
// the energy books, fold angles of every hinge, angles of every block.
#pragma once

#include "jl/sim/frame.h"

#include <QPointF>
#include <QString>

#include <vector>

namespace jl::ui {

// The energy curves, in the order of RunTraces::energy().
enum class EnergyTrace { Kinetic, Potential, Total, ImpactLoss, DampingLoss, HeldWork, UserWork, Balance, Count };
QString traceName(EnergyTrace t);

class RunTraces {
public:
    void clear();
    // Frames must come in time order; a frame at or before the last one
    // means the run was rewound (an edit in the past): later samples go.
    void append(const jl::Frame& frame);
    void setHistory(const std::vector<jl::Frame>& frames);
    // Forgets every sample after time t (the future was discarded).
    void truncateAfter(double t);

    int count() const { return int(time_.size()); }
    double startTime() const { return time_.empty() ? 0 : time_.front(); }
    double endTime() const { return time_.empty() ? 0 : time_.back(); }
    const std::vector<double>& time() const { return time_; }
    const std::vector<double>& energy(EnergyTrace t) const { return energy_[size_t(t)]; }
    int hingeCount() const { return hinges_; }  // hinge j is fold(j)
    int blockCount() const { return blocks_; }
    // phi of hinge j (1..N-1) at each sample, rad; NaN where the hinge did not exist yet.
    std::vector<double> fold(int hinge) const { return column(size_t(hinge - 1)); }
    // Angle of block i at each sample, rad, unwrapped (continuous across +-pi).
    std::vector<double> angle(int block) const { return column(size_t(hinges_ + block)); }
    // d theta / dt of block i over the frame interval ending at each sample
    // (frames carry poses, not velocities; the first sample is 0).
    std::vector<double> angularSpeed(int block) const;
    // The index of the last sample at or before t (0 when t is before the first).
    int sampleAt(double t) const;

private:
    // Entry k of every sample's row, in time order.
    std::vector<double> column(size_t k) const;

    std::vector<double> time_;
    std::vector<std::vector<double>> energy_ = std::vector<std::vector<double>>(size_t(EnergyTrace::Count));
    // One row a sample: the hinges' folds, then the blocks' angles. A
    // curve a hinge or block took 20,000 appends a frame on a 10,000-block
    // ladder, each vector growing on its own (a sixth of the UI thread's
    // time while it played); the plots read a few of them a few times a second.
    int hinges_ = 0, blocks_ = 0;
    std::vector<std::vector<double>> rows_;
};

// At most 4 points per bucket: the first, the lowest, the highest and the
// last sample of each of `buckets` equal slices of [t0, t1], in time order,
// so a peak one sample wide still shows; the plot costs the same however
// long the run. NaN samples are skipped.
std::vector<QPointF> decimate(const std::vector<double>& t, const std::vector<double>& y, double t0, double t1,
                              int buckets);

}  // namespace jl::ui
