#include "ui/teaching/run_traces.h"

#include <QObject>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl::ui {

QString traceName(EnergyTrace t) {
    switch (t) {
        case EnergyTrace::Kinetic:
            return QObject::tr("kinetic");
        case EnergyTrace::Potential:
            return QObject::tr("potential");
        case EnergyTrace::Total:
            return QObject::tr("total E");
        case EnergyTrace::ImpactLoss:
            return QObject::tr("impact loss");
        case EnergyTrace::DampingLoss:
            return QObject::tr("damping loss");
        case EnergyTrace::HeldWork:
            return QObject::tr("hand's work");
        case EnergyTrace::UserWork:
            return QObject::tr("drags' work");
        case EnergyTrace::Balance:
            return QObject::tr("balance");
        case EnergyTrace::Count:
            break;
    }
    return {};
}

void RunTraces::clear() {
    time_.clear();
    for (auto& e : energy_) e.clear();
    rows_.clear();
    hinges_ = blocks_ = 0;
}

void RunTraces::truncateAfter(double t) {
    const auto keep = size_t(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin());
    time_.resize(keep);
    for (auto& e : energy_) e.resize(keep);
    rows_.resize(keep);
}

void RunTraces::append(const jl::Frame& frame) {
    // Another scene (a different number of blocks) starts afresh.
    if (!time_.empty() && int(frame.poses.size()) != blocks_) clear();
    if (!time_.empty() && frame.time <= time_.back()) truncateAfter(std::nextafter(frame.time, -1e300));
    if (time_.empty()) {
        hinges_ = int(frame.hinges.size());
        blocks_ = int(frame.poses.size());
    }
    time_.push_back(frame.time);
    const jl::EnergyFrame& e = frame.energy;
    const double values[] = {e.kinetic,     e.potential, e.total(),  e.impactLoss,
                             e.dampingLoss, e.heldWork,  e.userWork, e.balance()};
    for (size_t i = 0; i < energy_.size(); ++i) energy_[i].push_back(values[i]);
    const auto hinges = size_t(hinges_);
    const bool first = rows_.empty();
    std::vector<double>& row = rows_.emplace_back(hinges + size_t(blocks_));
    const double* before = first ? nullptr : rows_[rows_.size() - 2].data() + hinges;
    for (size_t j = 0; j < hinges; ++j)
        row[j] = j < frame.hinges.size() ? frame.hinges[j].foldAngle : std::numeric_limits<double>::quiet_NaN();
    double* angle = row.data() + hinges;
    for (size_t i = 0; i < size_t(blocks_); ++i) {
        double a = frame.poses[i].angle;
        // Keep the curve continuous: a block turning past pi is not a jump.
        if (before) a += 2 * std::numbers::pi * std::round((before[i] - a) / (2 * std::numbers::pi));
        angle[i] = a;
    }
}

std::vector<double> RunTraces::column(size_t k) const {
    std::vector<double> out;
    out.reserve(rows_.size());
    for (const std::vector<double>& row : rows_) out.push_back(row[k]);
    return out;
}

void RunTraces::setHistory(const std::vector<jl::Frame>& frames) {
    clear();
    for (const jl::Frame& f : frames) append(f);
}

std::vector<double> RunTraces::angularSpeed(int block) const {
    const std::vector<double> a = angle(block);
    std::vector<double> w(a.size(), 0.0);
    for (size_t s = 1; s < a.size(); ++s) {
        const double dt = time_[s] - time_[s - 1];
        w[s] = dt > 0 ? (a[s] - a[s - 1]) / dt : w[s - 1];
    }
    return w;
}

int RunTraces::sampleAt(double t) const {
    const auto it = std::upper_bound(time_.begin(), time_.end(), t);
    return std::max(0, int(it - time_.begin()) - 1);
}

std::vector<QPointF> decimate(const std::vector<double>& t, const std::vector<double>& y, double t0, double t1,
                              int buckets) {
    std::vector<QPointF> out;
    const size_t n = std::min(t.size(), y.size());
    if (n == 0 || t1 <= t0 || buckets < 1) return out;
    const size_t first = size_t(std::lower_bound(t.begin(), t.begin() + long(n), t0) - t.begin());
    const size_t last = size_t(std::upper_bound(t.begin(), t.begin() + long(n), t1) - t.begin());
    // Include one sample either side so the curve runs to the plot's edges.
    const size_t from = first > 0 ? first - 1 : 0, to = std::min(n, last + 1);
    if (to - from <= size_t(4 * buckets)) {
        for (size_t s = from; s < to; ++s)
            if (!std::isnan(y[s])) out.emplace_back(t[s], y[s]);
        return out;
    }
    out.reserve(size_t(4 * buckets) + 2);
    const double width = (t1 - t0) / buckets;
    size_t s = from;
    while (s < to) {
        const long bucket = std::lround(std::floor((t[s] - t0) / width));
        size_t lo = s, hi = s, end = s;
        bool any = false;
        size_t firstOk = s, lastOk = s;
        for (; end < to && std::lround(std::floor((t[end] - t0) / width)) == bucket; ++end) {
            if (std::isnan(y[end])) continue;
            if (!any) firstOk = lo = hi = end;
            any = true;
            lastOk = end;
            if (y[end] < y[lo]) lo = end;
            if (y[end] > y[hi]) hi = end;
        }
        if (any) {
            size_t picks[] = {firstOk, lo, hi, lastOk};
            std::sort(std::begin(picks), std::end(picks));
            for (size_t i = 0; i < 4; ++i)
                if (i == 0 || picks[i] != picks[i - 1]) out.emplace_back(t[picks[i]], y[picks[i]]);
        }
        s = end;
    }
    return out;
}

}  // namespace jl::ui
