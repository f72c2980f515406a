// The design map (a window of its own, from the Ladder panel): two of the
// design's parameters as axes, one full first-ripple simulation per cell run
// on every core, the reach drawn as a heat map; a click opens that design as
// the current ladder (one undo step); the map exports as CSV, SVG and PNG.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/design/ripple_reach.h"
#include "ui/edit/document.h"

#include <QDialog>
#include <QFutureWatcher>

#include <atomic>
#include <memory>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QLabel;
class QProgressBar;
class QPushButton;
class QThreadPool;
class QTimer;

namespace jl::ui {

class DesignMapGrid;

// One axis as the form shows it: the parameter's name, shown unit and scale
// (lengths in mm), a sensible first range, and how far it may go.
struct AxisShown {
    jl::DesignParameter parameter;
    QString label;
    QString unit;
    double scale = 1;  // shown = SI * scale
    int decimals = 0;
    jl::DesignAxis first;     // SI
    double min = 0, max = 1;  // SI
};
const std::vector<AxisShown>& axesShown();
const AxisShown& axisShown(jl::DesignParameter p);

// The threads that run the design map's cells, apart from Qt's global pool
// (which the painting of every widget relies on) and from the live estimate's.
QThreadPool* designPool();

class DesignMap : public QDialog {
    Q_OBJECT
public:
    DesignMap(Document* doc, QWidget* parent = nullptr);
    ~DesignMap() override;

    void setAxes(const jl::DesignAxis& x, const jl::DesignAxis& y);
    jl::DesignAxis xAxis() const;
    jl::DesignAxis yAxis() const;
    // The design of a cell: the current ladder with the two axes' values.
    jl::Scene cellDesign(int column, int row) const;

    // Runs every cell the cache does not hold; never waits on a run.
    void compute();
    // Stops the runs (each sees the flag within one step); finished cells stay.
    void cancel();
    bool running() const { return running_; }
    int cellsToRun() const { return int(pending_.size()); }  // of the last compute
    DesignMapGrid* grid() const { return grid_; }

    bool exportCsv(const QString& path) const;
    bool exportSvg(const QString& path) const;
    bool exportPng(const QString& path) const;

signals:
    void mapFinished();  // every cell done, or the run cancelled

protected:
    void showEvent(QShowEvent* e) override;

private:
    struct Picker {
        QComboBox* parameter;
        QDoubleSpinBox *from, *to, *step;
    };
    Picker makePicker(const QString& name);
    jl::DesignAxis axisOf(const Picker& p) const;
    void setPicker(Picker& p, const jl::DesignAxis& a);
    void addPickerBox(QHBoxLayout* axes, const QString& title, const Picker& p);
    QHBoxLayout* makeRunBar();
    void followEdits();
    void showMap();  // the grid of the current ladder and axes, from the cache
    void onResult(int i);
    void onRunEnded();
    void openCell(int column, int row);
    void exportDialog();
    void updateStatus();

    Document* doc_;
    Picker x_, y_;
    DesignMapGrid* grid_;
    QProgressBar* progress_;
    QPushButton* computeButton_;
    QPushButton* cancelButton_;
    QPushButton* exportButton_;
    QLabel* status_;
    QTimer* follow_;  // a running map follows edits of the ladder and axes

    std::vector<double> xs_, ys_;  // SI values of the shown grid
    struct Pending {
        int column, row;
        QByteArray key;
    };
    std::vector<Pending> pending_;
    int done_ = 0;
    bool running_ = false;
    bool restartWhenChanged_ = false;
    std::shared_ptr<std::atomic<bool>> stop_;
    QFutureWatcher<jl::RippleReach> watcher_;
};

}  // namespace jl::ui
