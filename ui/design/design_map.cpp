#include "ui/design/design_map.h"

#include "jl/base/csv_writer.h"
#include "jl/design/design_check.h"
#include "ui/design/design_map_cache.h"
#include "ui/design/design_map_grid.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSvgGenerator>
#include <QThread>
#include <QThreadPool>
#include <QTimer>
#include <QUndoCommand>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <cmath>
#include <fstream>

namespace jl::ui {

namespace {

// More cells than this per axis are unreadable, and a long wait.
constexpr int kMostPerAxis = 60;

// Opening a cell's design: the whole scene before and after, one undo step
// that never merges with another.
class OpenDesign : public QUndoCommand {
public:
    OpenDesign(Document* doc, jl::Scene design, const QString& text)
        : QUndoCommand(text), doc_(doc), old_(doc->scene()), new_(std::move(design)) {}
    void redo() override { apply(new_); }
    void undo() override { apply(old_); }

private:
    void apply(const jl::Scene& s) {
        doc_->editableScene() = s;
        doc_->notifyChanged(SceneChange::Ladder);
    }
    Document* doc_;
    jl::Scene old_, new_;
};

// The largest of 1, 2, 5 times a power of ten not above x (> 0).
double roundStepBelow(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (const double m : {5.0, 2.0, 1.0})
        if (m * decade <= x) return m * decade;
    return decade;
}

// Five values about `value` (SI, the design being edited) in steps of 1, 2
// or 5 that the spin boxes can show: a designer of a 200-block ladder opens
// a map of 100 .. 300 blocks, not of 4 .. 12.
jl::DesignAxis rangeAbout(const AxisShown& a, double value) {
    const double shown = value * a.scale, lo = a.min * a.scale, hi = a.max * a.scale;
    const double step = std::max(std::pow(10.0, -a.decimals), roundStepBelow(std::abs(shown) / 4));
    int below = 2;
    while (below > 0 && shown - below * step < lo) --below;
    int above = 4 - below;
    while (above > 0 && shown + above * step > hi) --above;
    return {a.parameter, (shown - below * step) / a.scale, (shown + above * step) / a.scale, step / a.scale};
}

// Whether two values of an axis are the same design (a value read back from
// a spin box, or built as from + i step, may differ in the last bits).
bool sameValue(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({std::abs(a), std::abs(b), 1e-12}); }

QString shownValue(const AxisShown& a, double si) { return QString::number(si * a.scale, 'g', 6); }

QString axisTitle(const AxisShown& a) { return a.unit.isEmpty() ? a.label : QString("%1 (%2)").arg(a.label, a.unit); }
// A CSV column's name, its unit in brackets as in every table the programs write.
std::string columnTitle(const AxisShown& a) {
    return (a.unit.isEmpty() ? a.label : QString("%1 [%2]").arg(a.label, a.unit)).toStdString();
}

}  // namespace

const std::vector<AxisShown>& axesShown() {
    using P = jl::DesignParameter;
    static const std::vector<AxisShown> axes{
        {P::Blocks, QObject::tr("Blocks"), {}, 1, 0, {P::Blocks, 4, 12, 2}, 2, 2000},
        {P::Thickness, QObject::tr("Block thickness"), "mm", 1000, 1, {P::Thickness, 0.003, 0.012, 0.003}, 1e-4, 0.1},
        {P::Length, QObject::tr("Block length"), "mm", 1000, 1, {P::Length, 0.04, 0.08, 0.01}, 1e-3, 1},
        {P::Width, QObject::tr("Block width"), "mm", 1000, 1, {P::Width, 0.03, 0.06, 0.01}, 1e-3, 1},
        {P::Density, QObject::tr("Density"), "kg/m³", 1, 0, {P::Density, 300, 900, 200}, 1, 1e5},
        {P::HingeDamping, QObject::tr("Hinge damping"), "µN m s", 1e6, 2, {P::HingeDamping, 0, 4e-5, 1e-5}, 0, 1e-2},
        {P::TurnDuration, QObject::tr("Turn duration"), "s", 1, 3, {P::TurnDuration, 0.1, 0.5, 0.1}, 1e-3, 10},
    };
    return axes;
}

const AxisShown& axisShown(jl::DesignParameter p) {
    for (const AxisShown& a : axesShown())
        if (a.parameter == p) return a;
    return axesShown().front();
}

QThreadPool* designPool() {
    // Qt's own painting (image scaling and conversion in the raster engine)
    // splits its work over the global pool and waits for it: a map that
    // filled that pool with minute-long runs froze every repaint behind them.
    static QThreadPool* pool = [] {
        auto* p = new QThreadPool;  // lives as long as the program; its runs stop by their flag
        p->setMaxThreadCount(QThread::idealThreadCount());
        return p;
    }();
    return pool;
}

DesignMap::DesignMap(Document* doc, QWidget* parent) : QDialog(parent), doc_(doc) {
    setObjectName("designMap");
    setWindowTitle(tr("Design map: how far does the first ripple travel?"));
    setModal(false);
    auto* box = new QVBoxLayout(this);
    auto* axes = new QHBoxLayout;
    x_ = makePicker("x");
    y_ = makePicker("y");
    addPickerBox(axes, tr("Across (x)"), x_);
    addPickerBox(axes, tr("Up (y)"), y_);
    box->addLayout(axes);

    grid_ = new DesignMapGrid(this);
    grid_->setToolTip(
        tr("Each cell is one design, simulated from the top block's turn; hover for the numbers, click to open it."));
    box->addWidget(grid_, 1);
    box->addLayout(makeRunBar());
    box->addWidget(status_);

    followEdits();
    connect(computeButton_, &QPushButton::clicked, this, &DesignMap::compute);
    connect(cancelButton_, &QPushButton::clicked, this, &DesignMap::cancel);
    connect(exportButton_, &QPushButton::clicked, this, &DesignMap::exportDialog);
    connect(grid_, &DesignMapGrid::cellClicked, this, &DesignMap::openCell);
    connect(&watcher_, &QFutureWatcher<jl::RippleReach>::resultReadyAt, this, &DesignMap::onResult);
    connect(&watcher_, &QFutureWatcher<jl::RippleReach>::finished, this, &DesignMap::onRunEnded);

    setAxes(axisShown(jl::DesignParameter::Blocks).first, axisShown(jl::DesignParameter::Thickness).first);
    resize(900, 680);
}

// One axis's picker in a box of its own: the parameter, and its range.
void DesignMap::addPickerBox(QHBoxLayout* axes, const QString& title, const Picker& p) {
    auto* g = new QGroupBox(title, this);
    auto* form = new QFormLayout(g);
    form->addRow(tr("Parameter"), p.parameter);
    auto* range = new QHBoxLayout;
    range->addWidget(p.from);
    range->addWidget(new QLabel(tr("to"), g));
    range->addWidget(p.to);
    range->addWidget(new QLabel(tr("step"), g));
    range->addWidget(p.step);
    form->addRow(tr("From"), range);
    axes->addWidget(g);
}

// The runs' bar: compute, cancel, their progress, export; and the status
// line below it (made here, placed by the caller).
QHBoxLayout* DesignMap::makeRunBar() {
    auto* bar = new QHBoxLayout;
    computeButton_ = new QPushButton(tr("Compute"), this);
    computeButton_->setObjectName("computeMap");
    computeButton_->setToolTip(tr("Simulate every design of the map not simulated before, on every core."));
    cancelButton_ = new QPushButton(tr("Cancel"), this);
    cancelButton_->setObjectName("cancelMap");
    cancelButton_->setToolTip(tr("Stop the runs; the cells already done stay."));
    exportButton_ = new QPushButton(tr("Export..."), this);
    exportButton_->setObjectName("exportMap");
    exportButton_->setToolTip(tr("Save the map as CSV (numbers), SVG or PNG (picture)."));
    progress_ = new QProgressBar(this);
    progress_->setObjectName("mapProgress");
    progress_->setFormat(tr("%v of %m cells"));
    status_ = new QLabel(this);
    status_->setObjectName("mapStatus");
    bar->addWidget(computeButton_);
    bar->addWidget(cancelButton_);
    bar->addWidget(progress_, 1);
    bar->addWidget(exportButton_);
    return bar;
}

// The map follows edits of the ladder and of the axes, a moment after the
// last one: a running map starts again, a shown one is redrawn from the cache.
void DesignMap::followEdits() {
    follow_ = new QTimer(this);
    follow_->setSingleShot(true);
    follow_->setInterval(300);
    connect(follow_, &QTimer::timeout, this, [this] {
        const bool restart = std::exchange(restartWhenChanged_, false);
        if (restart)
            compute();
        else if (isVisible())
            showMap();
    });
    auto changed = [this] {
        if (running_) {
            restartWhenChanged_ = true;
            cancel();
        }
        follow_->start();
    };
    connect(doc_, &Document::changed, this, changed);
    for (Picker* p : {&x_, &y_}) {
        connect(p->parameter, &QComboBox::currentIndexChanged, this, [this, p, changed] {
            setPicker(*p, axisShown(jl::DesignParameter(p->parameter->currentData().toInt())).first);
            changed();
        });
        for (QDoubleSpinBox* s : {p->from, p->to, p->step}) connect(s, &QDoubleSpinBox::valueChanged, this, changed);
    }
}

DesignMap::~DesignMap() {
    // The runs hold their own copies of the designs and of the flag: they
    // end by themselves within a step, and nobody waits for them.
    if (stop_) stop_->store(true);
    watcher_.disconnect(this);
    watcher_.cancel();
}

DesignMap::Picker DesignMap::makePicker(const QString& name) {
    Picker p;
    p.parameter = new QComboBox(this);
    p.parameter->setObjectName(name + "Parameter");
    for (const AxisShown& a : axesShown()) p.parameter->addItem(a.label, int(a.parameter));
    auto spin = [&](const QString& part) {
        auto* s = new QDoubleSpinBox(this);
        s->setObjectName(name + part);
        s->setKeyboardTracking(false);
        return s;
    };
    p.from = spin("From");
    p.to = spin("To");
    p.step = spin("Step");
    return p;
}

void DesignMap::setPicker(Picker& p, const jl::DesignAxis& a) {
    const AxisShown& s = axisShown(a.parameter);
    const QSignalBlocker b0(p.parameter), b1(p.from), b2(p.to), b3(p.step);
    p.parameter->setCurrentIndex(p.parameter->findData(int(a.parameter)));
    for (QDoubleSpinBox* spin : {p.from, p.to, p.step}) {
        spin->setDecimals(s.decimals);
        spin->setRange(spin == p.step ? std::pow(10.0, -s.decimals) : s.min * s.scale, s.max * s.scale);
        spin->setSuffix(s.unit.isEmpty() ? QString() : " " + s.unit);
    }
    p.from->setValue(a.from * s.scale);
    p.to->setValue(a.to * s.scale);
    p.step->setValue(a.step * s.scale);
}

jl::DesignAxis DesignMap::axisOf(const Picker& p) const {
    const auto param = jl::DesignParameter(p.parameter->currentData().toInt());
    const AxisShown& s = axisShown(param);
    return {param, p.from->value() / s.scale, p.to->value() / s.scale, p.step->value() / s.scale};
}

jl::DesignAxis DesignMap::xAxis() const { return axisOf(x_); }
jl::DesignAxis DesignMap::yAxis() const { return axisOf(y_); }

void DesignMap::setAxes(const jl::DesignAxis& x, const jl::DesignAxis& y) {
    setPicker(x_, x);
    setPicker(y_, y);
    if (running_) {
        restartWhenChanged_ = true;
        cancel();
    }
    follow_->stop();
    if (std::exchange(restartWhenChanged_, false))
        compute();
    else
        showMap();
}

jl::Scene DesignMap::cellDesign(int column, int row) const {
    const jl::DesignAxis x = xAxis(), y = yAxis();
    return jl::withParameter(jl::withParameter(doc_->scene(), x.parameter, xs_[size_t(column)]), y.parameter,
                             ys_[size_t(row)]);
}

void DesignMap::showMap() {
    const jl::DesignAxis x = xAxis(), y = yAxis();
    xs_ = jl::axisValues(x);
    ys_ = jl::axisValues(y);
    const AxisShown &sx = axisShown(x.parameter), &sy = axisShown(y.parameter);
    QString problem;
    if (!doc_->scene().ladder)
        problem = tr("The scene has no ladder to vary.");
    else if (x.parameter == y.parameter)
        problem = tr("Pick two different parameters.");
    else if (xs_.empty() || ys_.empty())
        problem = tr("Each range must run upwards: from at most to.");
    else if (int(xs_.size()) > kMostPerAxis || int(ys_.size()) > kMostPerAxis)
        problem = tr("At most %1 values per axis: widen the step.").arg(kMostPerAxis);
    else
        // The scene file's ranges and loader, as for `jladder reach`: one
        // validation of a field, whichever way its value comes in.
        for (const jl::DesignAxis& a : {x, y})
            if (const std::string why = jl::axisProblem(doc_->scene(), a, std::size_t(kMostPerAxis));
                problem.isEmpty() && !why.empty())
                problem = QString::fromStdString(why);
    if (!problem.isEmpty()) {
        xs_.clear(), ys_.clear();
        grid_->setAxes(axisTitle(sx), {}, axisTitle(sy), {});
        status_->setText(problem);
        computeButton_->setEnabled(false);
        return;
    }
    QStringList xt, yt;
    for (double v : xs_) xt << shownValue(sx, v);
    for (double v : ys_) yt << shownValue(sy, v);
    grid_->setAxes(axisTitle(sx), xt, axisTitle(sy), yt);
    int cached = 0;
    const double currentX = jl::parameterValue(doc_->scene(), x.parameter);
    const double currentY = jl::parameterValue(doc_->scene(), y.parameter);
    for (int r = 0; r < grid_->rows(); ++r)
        for (int c = 0; c < grid_->columns(); ++c) {
            const jl::Scene design = cellDesign(c, r);
            if (sameValue(xs_[size_t(c)], currentX) && sameValue(ys_[size_t(r)], currentY)) grid_->setCurrent(c, r);
            if (const auto reach = ReachCache::shared().find(ReachCache::designKey(design))) {
                grid_->setCell(c, r, *reach);
                ++cached;
            }
        }
    progress_->setRange(0, grid_->columns() * grid_->rows());
    progress_->setValue(cached);
    updateStatus();
}

void DesignMap::compute() {
    cancel();
    follow_->stop();
    restartWhenChanged_ = false;
    showMap();
    pending_.clear();
    done_ = 0;
    if (xs_.empty()) return emit mapFinished();  // no map: the reason is on show
    QList<jl::Scene> designs;
    for (int r = 0; r < grid_->rows(); ++r)
        for (int c = 0; c < grid_->columns(); ++c)
            if (!grid_->cell(c, r)) {
                jl::Scene d = cellDesign(c, r);
                pending_.push_back({c, r, ReachCache::designKey(d)});
                designs.push_back(std::move(d));
            }
    if (designs.isEmpty()) {
        updateStatus();
        return emit mapFinished();
    }
    stop_ = std::make_shared<std::atomic<bool>>(false);
    running_ = true;
    // One engine per run; the runs share nothing but the flag that stops them.
    watcher_.setFuture(QtConcurrent::mapped(designPool(), std::move(designs), [stop = stop_](const jl::Scene& d) {
        return jl::firstRippleReach(d, stop.get());
    }));
    updateStatus();
}

void DesignMap::cancel() {
    if (!running_) return;
    stop_->store(true);
    watcher_.cancel();
    running_ = false;
    updateStatus();
}

void DesignMap::onResult(int i) {
    const jl::RippleReach r = watcher_.resultAt(i);
    const Pending& p = pending_[size_t(i)];
    ReachCache::shared().keep(p.key, r);
    if (r.cancelled) return;
    grid_->setCell(p.column, p.row, r);
    ++done_;
    progress_->setValue(progress_->value() + 1);
    updateStatus();
}

void DesignMap::onRunEnded() {
    running_ = false;
    updateStatus();
    emit mapFinished();
}

void DesignMap::updateStatus() {
    if (xs_.empty()) return;
    const int cells = grid_->columns() * grid_->rows();
    const int shown = progress_->value();
    cancelButton_->setEnabled(running_);
    computeButton_->setEnabled(!running_ && shown < cells);
    QString s = tr("%1 of %2 designs simulated").arg(shown).arg(cells);
    if (running_)
        s += tr(", %1 running on %2 threads").arg(int(pending_.size()) - done_).arg(designPool()->maxThreadCount());
    else if (shown < cells)
        s += tr(": Compute simulates the rest");
    status_->setText(s + tr(". Each cell is the ladder being edited (framed when on the map) with two values changed, "
                            "its top block turned as its script says."));
}

void DesignMap::openCell(int column, int row) {
    if (!grid_->cell(column, row)) return;
    const jl::Scene design = cellDesign(column, row);
    if (design == doc_->scene()) return;
    const AxisShown &sx = axisShown(xAxis().parameter), &sy = axisShown(yAxis().parameter);
    const QString text =
        tr("Open design %1 %2, %3 %4")
            .arg(sx.label, shownValue(sx, xs_[size_t(column)]) + (sx.unit.isEmpty() ? "" : " " + sx.unit), sy.label,
                 shownValue(sy, ys_[size_t(row)]) + (sy.unit.isEmpty() ? "" : " " + sy.unit));
    doc_->undoStack()->push(new OpenDesign(doc_, design, text));
}

bool DesignMap::exportCsv(const QString& path) const {
    std::ofstream out(path.toStdString());
    const AxisShown &sx = axisShown(xAxis().parameter), &sy = axisShown(yAxis().parameter);
    CsvWriter csv(out);
    csv.row(columnTitle(sx), columnTitle(sy), "hinges", "reached", "mean time between flips [s]", "failure");
    for (int r = 0; r < grid_->rows(); ++r)
        for (int c = 0; c < grid_->columns(); ++c) {
            const auto cell = grid_->cell(c, r);
            const std::string x = shownValue(sx, xs_[size_t(c)]).toStdString(),
                              y = shownValue(sy, ys_[size_t(r)]).toStdString();
            if (cell)
                csv.row(x, y, cell->hinges, cell->reached, cell->meanTimeBetweenFlips, cell->failure);
            else
                csv.row(x, y, "", "", "", "");
        }
    return bool(out);
}

bool DesignMap::exportSvg(const QString& path) const {
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(grid_->size());
    svg.setViewBox(grid_->rect());
    svg.setTitle(windowTitle());
    QPainter painter;
    if (!painter.begin(&svg)) return false;
    grid_->render(&painter);
    return painter.end();
}

bool DesignMap::exportPng(const QString& path) const { return grid_->grab().save(path, "PNG"); }

void DesignMap::exportDialog() {
    QString filter;
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export the design map"), "design-map.csv",
                                     tr("Numbers (*.csv);;Picture, SVG (*.svg);;Picture, PNG (*.png)"), &filter);
    if (path.isEmpty()) return;
    const QString suffix = QFileInfo(path).suffix().toLower();
    const bool ok = suffix == "svg" ? exportSvg(path) : suffix == "png" ? exportPng(path) : exportCsv(path);
    if (!ok) QMessageBox::warning(this, tr("Export failed"), tr("Could not write %1.").arg(path));
}

void DesignMap::showEvent(QShowEvent* e) {
    QDialog::showEvent(e);
    // Opened on a design off the map: the map moves to it (each axis
    // keeps its parameter). Cells already simulated are kept by design.
    if (!running_ && doc_->scene().ladder) {
        // An axis the design is on (or has no value for) stays as it is.
        const auto about = [this](const jl::DesignAxis& a) {
            const double v = jl::parameterValue(doc_->scene(), a.parameter);
            if (!std::isfinite(v) || !(v > 0)) return a;
            for (const double w : jl::axisValues(a))
                if (sameValue(w, v)) return a;
            return rangeAbout(axisShown(a.parameter), v);
        };
        const jl::DesignAxis x = xAxis(), y = yAxis(), nx = about(x), ny = about(y);
        if (!(nx == x) || !(ny == y)) return setAxes(nx, ny);
    }
    if (!running_) showMap();
}

}  // namespace jl::ui
