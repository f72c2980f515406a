#include "ui/teaching/run_plots.h"

#include "ui/teaching/time_chart.h"

#include <QBoxLayout>
#include <QChart>
#include <QCoreApplication>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLayout>
#include <QLineEdit>
#include <QLineSeries>
#include <QMessageBox>
#include <QPainter>
#include <QRegularExpression>
#include <QSvgGenerator>
#include <QToolButton>
#include <QVBoxLayout>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
// How many fold angles and angular speeds a ladder shows at first.
constexpr int kHingesPlotted = 5, kBlocksPlotted = 3;

// Ten colours told apart by most eyes and projectors (Tableau 10).
QColor curveColor(int i) {
    static const QColor palette[] = {{31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
                                     {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
    return palette[size_t(i) % std::size(palette)];
}

struct EnergyLook {
    QColor color;
    qreal width;
    Qt::PenStyle style;
};

EnergyLook energyLook(EnergyTrace t) {
    switch (t) {
        case EnergyTrace::Kinetic:
            return {{214, 39, 40}, 1.6, Qt::SolidLine};
        case EnergyTrace::Potential:
            return {{31, 119, 180}, 1.6, Qt::SolidLine};
        case EnergyTrace::Total:
            return {{20, 20, 20}, 2.4, Qt::SolidLine};
        case EnergyTrace::ImpactLoss:
            return {{255, 127, 14}, 1.6, Qt::DashLine};
        case EnergyTrace::DampingLoss:
            return {{140, 86, 75}, 1.6, Qt::DashLine};
        case EnergyTrace::HeldWork:
            return {{44, 160, 44}, 1.6, Qt::DashDotLine};
        case EnergyTrace::UserWork:
            return {{23, 190, 207}, 1.6, Qt::DashDotLine};
        case EnergyTrace::Balance:
            return {{148, 103, 189}, 2.8, Qt::SolidLine};
        case EnergyTrace::Count:
            break;
    }
    return {};
}

}  // namespace

std::vector<int> parseIndexList(const QString& text, int lo, int hi) {
    std::vector<int> out;
    static const QRegularExpression item(R"((\d+)\s*(?:-\s*(\d+))?)");
    for (auto it = item.globalMatch(text); it.hasNext();) {
        const auto m = it.next();
        const int a = m.captured(1).toInt(), b = m.captured(2).isEmpty() ? a : m.captured(2).toInt();
        for (int i = std::max(lo, std::min(a, b)); i <= std::min(hi, std::max(a, b)) && out.size() < 64; ++i)
            out.push_back(i);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

QString indexListText(const std::vector<int>& indices) {
    QStringList parts;
    for (size_t i = 0; i < indices.size();) {
        size_t j = i;
        while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
        parts << (j > i + 1 ? QString("%1-%2").arg(indices[i]).arg(indices[j]) : QString::number(indices[i]));
        if (j == i + 1) parts << QString::number(indices[j]);
        i = j + 1;
    }
    return parts.join(", ");
}

RunPlots::RunPlots(QWidget* parent) : QWidget(parent) {
    setObjectName("plots");
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(2, 2, 2, 2);
    box->setSpacing(2);
    auto* row = new QHBoxLayout;
    hingeField_ = new QLineEdit(this);
    hingeField_->setObjectName("plotHinges");
    hingeField_->setToolTip(tr("Hinges whose fold angle is plotted, e.g. 1-3, 5 (hinge j joins blocks j-1 and j)."));
    blockField_ = new QLineEdit(this);
    blockField_->setObjectName("plotBlocks");
    blockField_->setToolTip(tr("Blocks whose angular speed is plotted, e.g. 0-2 (block 0 is the top one)."));
    auto* exportButton = new QToolButton(this);
    exportButton->setText(tr("Export..."));
    exportButton->setToolTip(tr("Save the plots as a picture (PNG) or a drawing (SVG)."));
    row->addWidget(new QLabel(tr("Hinges"), this));
    row->addWidget(hingeField_, 1);
    row->addWidget(new QLabel(tr("Blocks"), this));
    row->addWidget(blockField_, 1);
    row->addWidget(exportButton);
    box->addLayout(row);

    chartsArea_ = new QWidget(this);
    chartsLayout_ = new QBoxLayout(QBoxLayout::LeftToRight, chartsArea_);
    auto* charts = chartsLayout_;
    charts->setContentsMargins(0, 0, 0, 0);
    charts->setSpacing(0);
    charts_[0] = new TimeChart(tr("Energy and its books"), tr("energy (J)"), chartsArea_);
    charts_[1] = new TimeChart(tr("Fold angles"), tr("degrees"), chartsArea_);
    charts_[2] = new TimeChart(tr("Angular speeds"), tr("rad/s"), chartsArea_);
    // The admissible fold angles: open (0) to face to face (180).
    charts_[1]->setValueRange(0, 180, 45);
    for (TimeChart* c : charts_) {
        charts->addWidget(c, 1);
        connect(c, &TimeChart::seekRequested, this, &RunPlots::seekRequested);
        // One time axis for the eye: the three plots keep the same left and right edges.
        connect(c->chart(), &QChart::plotAreaChanged, this,
                [this] { QTimer::singleShot(0, this, &RunPlots::alignCharts); });
    }
    box->addWidget(chartsArea_, 1);
    for (int t = 0; t < int(EnergyTrace::Count); ++t) {
        const EnergyLook look = energyLook(EnergyTrace(t));
        energyCurves_[size_t(t)] = charts_[0]->addCurve(traceName(EnergyTrace(t)), look.color, look.width, look.style);
    }
    // Every energy curve starts shown: a hidden one (damping, a drag's work)
    // was missing just when it mattered, and its legend entry looked cut.
    rebuildChosenCurves();

    refreshTimer_.setInterval(150);
    refreshTimer_.setSingleShot(true);
    connect(&refreshTimer_, &QTimer::timeout, this, &RunPlots::refresh);
    // Before a run is recorded any index goes; after, only those that exist.
    connect(hingeField_, &QLineEdit::editingFinished, this, [this] {
        setChosen(parseIndexList(hingeField_->text(), 1, traces_.count() ? traces_.hingeCount() : 9999), blocks_);
    });
    connect(blockField_, &QLineEdit::editingFinished, this, [this] {
        setChosen(hinges_, parseIndexList(blockField_->text(), 0, traces_.count() ? traces_.blockCount() - 1 : 9999));
    });
    connect(exportButton, &QToolButton::clicked, this, &RunPlots::exportDialog);
}

// A field losing the focus while the window closes must not touch charts being deleted.
RunPlots::~RunPlots() {
    hingeField_->disconnect(this);
    blockField_->disconnect(this);
}

void RunPlots::setChosen(const std::vector<int>& hinges, const std::vector<int>& blocks) {
    // The fields say they are finished whenever they lose the focus.
    if (hinges == hinges_ && blocks == blocks_ && int(foldCurves_.size()) == int(hinges.size())) return;
    hinges_ = hinges;
    blocks_ = blocks;
    rebuildChosenCurves();
    refresh();
}

void RunPlots::rebuildChosenCurves() {
    for (QLineSeries* s : foldCurves_) charts_[1]->chart()->removeSeries(s), delete s;
    for (QLineSeries* s : speedCurves_) charts_[2]->chart()->removeSeries(s), delete s;
    foldCurves_.clear();
    speedCurves_.clear();
    for (size_t i = 0; i < hinges_.size(); ++i)
        foldCurves_.push_back(charts_[1]->addCurve(tr("hinge %1").arg(hinges_[i]), curveColor(int(i))));
    for (size_t i = 0; i < blocks_.size(); ++i)
        speedCurves_.push_back(charts_[2]->addCurve(tr("block %1").arg(blocks_[i]), curveColor(int(i))));
    hingeField_->setText(indexListText(hinges_));
    blockField_->setText(indexListText(blocks_));
    charts_[1]->fitLegend();
    charts_[2]->fitLegend();
}

// Up to `count` indices from `first` to `last`, both ends included, evenly
// apart: on a long ladder the curves tell how the motion travels down it
// (the first five hinges of ten told nothing of the bottom half).
std::vector<int> spreadOver(int first, int last, int count) {
    std::vector<int> out;
    const int n = last - first + 1;
    if (n <= 0) return out;
    if (n <= count) {
        for (int i = first; i <= last; ++i) out.push_back(i);
        return out;
    }
    for (int k = 0; k < count; ++k) out.push_back(first + int(std::lround(double(k) * (n - 1) / (count - 1))));
    return out;
}

// The time axis ends where the timeline's does: at the scene's length, or
// where the run has got to past it (never at an empty tail).
double RunPlots::span() const { return std::max(duration_, traces_.endTime()); }

void RunPlots::setDuration(double seconds) {
    duration_ = std::max(0.1, seconds);
    scheduleRefresh();
}

void RunPlots::scheduleRefresh() {
    dirty_ = true;
    if (!refreshTimer_.isActive()) refreshTimer_.start();
}

void RunPlots::append(const jl::Frame& frame) {
    traces_.append(frame);
    // A ladder of another size: choose hinges and blocks that exist.
    if (traces_.hingeCount() != knownHinges_) {
        knownHinges_ = traces_.hingeCount();
        chooseFirst();
    }
    scheduleRefresh();
}

void RunPlots::setTurning(int count) {
    if (count == turning_) return;
    turning_ = count;
    if (traces_.count() > 0) chooseFirst();
}

// What a scene shows at first: hinges and turning blocks spread over the
// ladder.
void RunPlots::chooseFirst() {
    const int blocks = turning_ >= 0 ? std::min(turning_, traces_.blockCount()) : traces_.blockCount();
    setChosen(spreadOver(1, knownHinges_, kHingesPlotted), spreadOver(0, blocks - 1, kBlocksPlotted));
}

void RunPlots::setHistory(const std::vector<jl::Frame>& frames) {
    traces_.clear();
    for (const jl::Frame& f : frames) append(f);
    refresh();
}

void RunPlots::setEvents(std::shared_ptr<const std::vector<jl::Event>> events) {
    events_ = events;
    for (TimeChart* c : charts_) c->setEvents(events);
}

void RunPlots::setCursorTime(double t) {
    for (TimeChart* c : charts_) c->setCursorTime(t);
}

void RunPlots::showStatus(const SimStatus& s) {
    if (s.loadSerial != loadSerial_) {
        loadSerial_ = s.loadSerial;
        traces_.clear();
        scheduleRefresh();
    }
    const double head = std::max(0, s.frameCount - 1) * s.interval;
    if (traces_.count() > 0 && traces_.endTime() > head + s.interval * 0.5) {
        traces_.truncateAfter(head + s.interval * 0.5);
        scheduleRefresh();
    }
    // Every frame of the run, in order, from the first: never only the ones
    // that were on screen (a seek or an edit computes many between two looks).
    if (s.newFrames)
        for (const auto& f : *s.newFrames)
            if (traces_.count() == 0 || f->time > traces_.endTime()) append(*f);
    // New events repaint the charts whole: with the curves, at the refresh's
    // pace, not at every status (a long ladder's bottom knocks dozens of
    // times a second, and three charts repainted each time held the window
    // to a few pictures a second).
    if (s.events != events_) {
        events_ = s.events;
        scheduleRefresh();
    }
    setCursorTime(s.frame ? s.frame->time : 0);
}

void RunPlots::refresh() {
    refreshTimer_.stop();
    setEvents(events_);
    alignPasses_ = 0;
    dirty_ = false;
    const double t1 = span();
    const std::vector<double>& t = traces_.time();
    for (TimeChart* c : charts_) c->setTimeRange(0, t1);
    auto buckets = [](TimeChart* c) { return std::max(100, int(c->chart()->plotArea().width())); };
    // Millijoules for a wooden toy (0.02 kg blocks): the axis reads in whole numbers.
    double largest = 0;
    for (int e = 0; e < int(EnergyTrace::Count); ++e)
        for (double v : traces_.energy(EnergyTrace(e))) largest = std::max(largest, std::abs(v));
    energyScale_ = largest >= 1 ? 1.0 : largest >= 1e-3 || largest == 0 ? 1e3 : 1e6;
    // The books in words: how far E strays from E0 + W - D over the whole run.
    double books = 0;
    for (double v : traces_.energy(EnergyTrace::Balance)) books = std::max(books, std::abs(v));
    // In large type a third of a projector's width holds the short form.
    charts_[0]->chart()->setTitle(traces_.count() == 0 ? tr("Energy and its books")
                                  : large_             ? tr("Energy (books: %1 J)").arg(books, 0, 'g', 2)
                                           : tr("Energy and its books (they balance to %1 J)").arg(books, 0, 'g', 2));
    charts_[0]->valueAxis()->setTitleText(energyScale_ == 1     ? tr("energy (J)")
                                          : energyScale_ == 1e3 ? tr("energy (mJ)")
                                                                : tr("energy (µJ)"));
    for (int e = 0; e < int(EnergyTrace::Count); ++e) {
        std::vector<QPointF> pts = decimate(t, traces_.energy(EnergyTrace(e)), 0, t1, buckets(charts_[0]));
        for (QPointF& p : pts) p.setY(p.y() * energyScale_);
        charts_[0]->setPoints(energyCurves_[size_t(e)], pts);
    }
    for (size_t i = 0; i < hinges_.size(); ++i) {
        std::vector<QPointF> pts;
        if (hinges_[i] <= traces_.hingeCount()) pts = decimate(t, traces_.fold(hinges_[i]), 0, t1, buckets(charts_[1]));
        for (QPointF& p : pts) p.setY(p.y() * (180 / std::numbers::pi));
        charts_[1]->setPoints(foldCurves_[i], pts);
    }
    for (size_t i = 0; i < blocks_.size(); ++i) {
        std::vector<QPointF> pts;
        if (blocks_[i] < traces_.blockCount())
            pts = decimate(t, traces_.angularSpeed(blocks_[i]), 0, t1, buckets(charts_[2]));
        charts_[2]->setPoints(speedCurves_[i], pts);
    }
    charts_[0]->fitValues(1e-6 * energyScale_);
    charts_[2]->fitValues(1);
    charts_[1]->setVisible(traces_.hingeCount() > 0 || traces_.count() == 0);
}

void RunPlots::alignCharts() {
    if (sideBySide_) return;  // each chart has its own time axis then
    // Qt lays the axes out again after each change of margins, and label
    // widths shift by a pixel or two: a few passes settle it, more chase noise.
    if (++alignPasses_ > 4) return;
    // Measure laid-out charts only: margins set a moment ago take effect at the next layout.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
    double left = -1e9, right = 1e9;
    for (TimeChart* c : charts_)
        if (c->isVisible()) left = std::max(left, c->naturalLeft()), right = std::min(right, c->naturalRight());
    for (TimeChart* c : charts_)
        if (c->isVisible()) c->setExtraMargins(left - c->naturalLeft(), c->naturalRight() - right);
}

void RunPlots::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    alignPasses_ = 0;
    scheduleRefresh();  // tick counts follow the charts' heights
    // A wide, low dock (under the view) shows the charts side by side; a
    // tall one (beside it, or an exported page) stacks them on one time axis.
    const bool wide = width() > 1.6 * height();
    if (wide == sideBySide_) return;
    sideBySide_ = wide;
    chartsLayout_->setDirection(wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
    for (TimeChart* c : charts_) c->setExtraMargins(0, 0);
}

void RunPlots::setLarge(bool large) {
    large_ = large;
    dirty_ = true;
    alignPasses_ = 0;
    for (TimeChart* c : charts_) c->setLarge(large);
}

void RunPlots::settle() {
    if (dirty_) refresh();
    alignPasses_ = 0;
    for (int pass = 0; pass < 4; ++pass) alignCharts();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
}

QImage RunPlots::renderImage(const QSize& size) {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::white);
    QPainter p(&image);
    p.setRenderHint(QPainter::Antialiasing);
    if (!chartsArea_->isVisible()) chartsArea_->resize(size);
    settle();
    const QSize area = chartsArea_->size();
    p.scale(double(size.width()) / area.width(), double(size.height()) / area.height());
    chartsArea_->render(&p, QPoint(), QRegion(), QWidget::DrawChildren);
    return image;
}

bool RunPlots::savePng(const QString& path, const QSize& size, QString* error) {
    if (renderImage(size).save(path, "PNG")) return true;
    if (error) *error = tr("Could not write the picture %1.").arg(path);
    return false;
}

bool RunPlots::saveSvg(const QString& path, const QSize& size, QString* error) {
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setSize(size);
    svg.setResolution(96);  // what browsers and slide programs take a pixel to be
    svg.setViewBox(QRect(QPoint(), size));
    svg.setTitle(tr("Jacob's ladder: energies, fold angles and angular speeds"));
    if (!chartsArea_->isVisible()) chartsArea_->resize(size);
    settle();
    const QSize area = chartsArea_->size();
    QPainter p;
    if (!p.begin(&svg)) {
        if (error) *error = tr("Could not write the drawing %1.").arg(path);
        return false;
    }
    p.scale(double(size.width()) / area.width(), double(size.height()) / area.height());
    chartsArea_->render(&p, QPoint(), QRegion(), QWidget::DrawChildren);
    return p.end();
}

void RunPlots::exportDialog() {
    QString filter;
    const QString path = QFileDialog::getSaveFileName(this, tr("Export the plots"), "plots.png",
                                                      tr("PNG picture (*.png);;SVG drawing (*.svg)"), &filter);
    if (path.isEmpty()) return;
    QString error;
    const QSize size = chartsArea_->size() * 2;
    const bool ok = path.endsWith(".svg", Qt::CaseInsensitive) ? saveSvg(path, chartsArea_->size(), &error)
                                                               : savePng(path, size, &error);
    if (!ok) QMessageBox::warning(this, tr("Export the plots"), error);
}

}  // namespace jl::ui
