// The Plots dock: energies and the energy books, fold angles of chosen
// hinges and angular speeds of chosen blocks against time, tied to the
// timeline (cursor, event marks, click to seek); export as PNG or SVG.
#pragma once

#include "ui/play/sim_status.h"
#include "ui/teaching/run_traces.h"

#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <vector>

class QBoxLayout;
class QLineEdit;
class QLineSeries;

namespace jl::ui {

class TimeChart;

class RunPlots : public QWidget {
    Q_OBJECT
public:
    explicit RunPlots(QWidget* parent = nullptr);
    ~RunPlots() override;

    // Follows the running simulation: a new load starts afresh, frames
    // reaching past the last sample are appended, a rewound run (the future
    // discarded) is cut back; the cursor and the marks follow the timeline.
    void showStatus(const SimStatus& status);
    // A whole recorded run at once (tests, exports, the command line).
    void setHistory(const std::vector<jl::Frame>& frames);
    void append(const jl::Frame& frame);
    void setEvents(std::shared_ptr<const std::vector<jl::Event>> events);
    void setCursorTime(double t);
    void setDuration(double seconds);  // the scene's suggested length: the time axis spans at least this

    // Which hinges (1..N-1) and blocks (0..N-1) are plotted; "1-3, 5" in the fields.
    void setChosen(const std::vector<int>& hinges, const std::vector<int>& blocks);
    // How many of a frame's poses turn: the blocks and boxes, before the
    // scene's particles, whose angular speed is always 0. The blocks plotted
    // at first are chosen among these.
    void setTurning(int count);
    const std::vector<int>& chosenHinges() const { return hinges_; }
    const std::vector<int>& chosenBlocks() const { return blocks_; }

    // Rebuilds the curves now (they are otherwise rebuilt a few times a second).
    void refresh();
    void setLarge(bool large);

    const RunTraces& traces() const { return traces_; }
    TimeChart* energyChart() const { return charts_[0]; }
    TimeChart* foldChart() const { return charts_[1]; }
    TimeChart* speedChart() const { return charts_[2]; }
    QLineSeries* energyCurve(EnergyTrace t) const { return energyCurves_[size_t(t)]; }
    // The energy curves are in J times this (1e3: mJ, 1e6: µJ), chosen for the run's size.
    double energyScale() const { return energyScale_; }

    // Low and wide: under the view it must leave the view room.
    QSize sizeHint() const override { return {900, 240}; }

    QImage renderImage(const QSize& size);
    bool savePng(const QString& path, const QSize& size, QString* error);
    bool saveSvg(const QString& path, const QSize& size, QString* error);

signals:
    void seekRequested(double time);

protected:
    void resizeEvent(QResizeEvent* e) override;

private:
    void chooseFirst();
    void rebuildChosenCurves();
    void alignCharts();
    // Lays the charts out now (Qt does it at the next turn of the event loop): before drawing into a file.
    void settle();
    void scheduleRefresh();
    double span() const;
    void exportDialog();

    RunTraces traces_;
    std::array<TimeChart*, 3> charts_{};
    std::array<QLineSeries*, size_t(EnergyTrace::Count)> energyCurves_{};
    std::vector<QLineSeries*> foldCurves_, speedCurves_;
    std::vector<int> hinges_{1, 2, 3, 4, 5}, blocks_{0, 1, 2};
    QLineEdit* hingeField_;
    QLineEdit* blockField_;
    QWidget* chartsArea_;
    QBoxLayout* chartsLayout_;
    bool sideBySide_ = true;  // as under the view, where the window first puts it
    QTimer refreshTimer_;
    bool dirty_ = false;
    std::shared_ptr<const std::vector<jl::Event>> events_;  // marked on the charts at the next refresh
    QWidget* fieldsRow_;                                    // hinges, blocks, export: hidden in large type
    bool large_ = false;
    double duration_ = 5;
    double energyScale_ = 1e3;
    std::uint64_t loadSerial_ = ~std::uint64_t(0);
    int knownHinges_ = -1;
    int turning_ = -1;  // -1: every pose turns
    int alignPasses_ = 0;
};

// Up to `count` indices from `first` to `last` (both included), evenly apart.
std::vector<int> spreadOver(int first, int last, int count);
// "1-3, 5" -> {1, 2, 3, 5}, kept within [lo, hi]; nonsense is skipped.
std::vector<int> parseIndexList(const QString& text, int lo, int hi);
QString indexListText(const std::vector<int>& indices);

}  // namespace jl::ui
