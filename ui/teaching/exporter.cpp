#include "ui/teaching/exporter.h"

#include "jl/sim/event_csv.h"
#include "jl/sim/frame_csv.h"
#include "jl/sim/recording.h"
#include "jl/sim/simulation.h"
#include "ui/view3d/view_capture.h"

#include <QDir>
#include <QFileInfo>
#include <QPainter>
#include <QProcess>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cmath>
#include <optional>
#include <sstream>

namespace jl::ui {

namespace {

ExportResult failed(const QString& why) { return {false, why, {}}; }

// A painter draws at its own size (the 3-D view at its size on screen):
// its picture is scaled whole into the size asked for, centred, the margin
// the colour of its corner (the room's), so no part of the view is lost.
QImage fitted(const QImage& picture, const QSize& size) {
    if (picture.isNull() || picture.size() == size) return picture;
    const QImage scaled = picture.scaled(size, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    QImage out(size, QImage::Format_RGB32);
    out.fill(picture.pixelColor(0, 0));
    QPainter p(&out);
    p.drawImage((size.width() - scaled.width()) / 2, (size.height() - scaled.height()) / 2, scaled);
    return out;
}

// `picture` saved as PNG at `path`, or why not (a null picture: the 3-D
// view, which draws only on screen, drew nothing).
std::optional<QString> savePicture(const QImage& picture, const QString& path) {
    if (picture.isNull()) return QObject::tr("The 3-D view drew nothing: it has to be on screen to be pictured.");
    if (!picture.save(path, "PNG")) return QObject::tr("Could not write the picture %1.").arg(path);
    return std::nullopt;
}

// Written whole or not at all.
std::optional<QString> saveText(const QString& path, const std::string& text) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(text.data(), qint64(text.size())) != qint64(text.size()) ||
        !file.commit())
        return QObject::tr("Could not write %1: %2").arg(path, file.errorString());
    return std::nullopt;
}

// Poses of a whole range fit in memory unless the ladder is huge; then the
// side view frames as it goes (growing, never shrinking).
constexpr double kMaxPosesInMemory = 4e6;

}  // namespace

ExportResult Exporter::viewPicture(LadderView* view, const QString& path) {
    if (const auto error = savePicture(view ? captureView(view) : QImage(), path)) return failed(*error);
    return {true, {}, {path}};
}

ExportResult Exporter::sideViewPicture(const jl::Scene& scene, const jl::Frame& frame, const QSize& size,
                                       const SideViewOptions& look, const QString& path) {
    SideView view;
    view.setOptions(look);
    view.setScene(scene);
    view.showFrame(frame);
    if (!view.render(size).save(path, "PNG")) return failed(QObject::tr("Could not write the picture %1.").arg(path));
    return {true, {}, {path}};
}

int Exporter::frameCount(double from, double to, double fps) {
    if (!(fps > 0) || !(to >= from)) return 0;
    return int(std::floor((to - from) * fps + 1e-9)) + 1;
}

namespace {

// The frames of a recorded run from `from` on, handed to `each` as they come.
struct FramesFrom : jl::RecordTarget {
    double from = 0;
    bool ribbons = false;  // the frames are drawn in 3-D, ribbons and all
    std::function<bool(jl::Frame&&)> each;
    bool drawsRibbons() const override { return ribbons; }
    bool frame(const jl::Frame& f) override { return f.time < from - 1e-9 || each(jl::Frame(f)); }
    bool event(const jl::Event&) override { return true; }
};

}  // namespace

ExportResult Exporter::imageSequence(const jl::Scene& scene, const SequenceRequest& r) {
    const int total = frameCount(r.from, r.to, r.fps);
    if (total == 0)
        return failed(QObject::tr("The time range is empty: choose an end after the start and a positive frame rate."));
    if (r.size.isEmpty()) return failed(QObject::tr("The picture size is empty."));
    if (!QDir().mkpath(r.directory)) return failed(QObject::tr("Could not make the folder %1.").arg(r.directory));
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) {
        return failed(QObject::tr("The scene does not build: %1")
                          .arg(QString::fromStdString(built.errors.empty() ? std::string() : built.errors.front())));
    }
    jl::Simulation& sim = *built.simulation;

    SideView view;
    view.setOptions(r.look);
    view.setScene(scene);
    // Picture i shows the run at exactly from + i / fps, recorded as the
    // table exports are (jl/sim/recording.h).
    const jl::FrameGrid grid{r.from, 1 / r.fps};
    ExportResult result{true, {}, {}};
    int drawn = 0;
    const auto draw = [&](const jl::Frame& f) {
        if (drawn >= total) return true;
        QImage picture;
        if (r.painter) {
            picture = fitted(r.painter(f), r.size);
        } else {
            view.showFrame(f);
            picture = view.render(r.size);
        }
        const QString path = QDir(r.directory).filePath(QString("frame_%1.png").arg(drawn, 5, 10, QChar('0')));
        if (const auto error = savePicture(picture, path)) {
            result = failed(*error);
            return false;
        }
        result.files << path;
        ++drawn;
        if (r.progress && !r.progress(drawn, total)) {
            result = failed(QObject::tr("Cancelled after %1 of %2 pictures.").arg(drawn).arg(total));
            return false;
        }
        return true;
    };
    FramesFrom target;
    target.from = r.from;
    target.ribbons = bool(r.painter);
    std::vector<jl::Frame> frames;
    const bool twoPasses = !r.painter && double(total) * sim.blockCount() <= kMaxPosesInMemory;
    // Two passes when they fit in memory: first the whole range, so that one
    // framing holds every picture; else each picture as its frame comes.
    if (twoPasses)
        target.each = [&](jl::Frame&& f) {
            frames.push_back(std::move(f));
            return true;
        };
    else
        target.each = [&](jl::Frame&& f) { return draw(f); };
    const jl::Recording run = jl::record(sim, r.to, grid, &target);
    if (!result.ok) return result;
    if (!run.failure.empty())
        return failed(
            QObject::tr("The run stopped at %1 s: %2").arg(run.time).arg(QString::fromStdString(run.failure)));
    if (twoPasses) {
        QRectF all;
        for (const jl::Frame& f : frames) all = all.united(view.extentOf(f));
        view.setFraming(all.adjusted(-0.1 * all.width(), -0.06 * all.height(), 0.1 * all.width(), 0.06 * all.height()));
        for (const jl::Frame& f : frames)
            if (!draw(f)) return result;
    }
    return result;
}

ExportResult Exporter::eventsCsv(const std::vector<jl::Event>& events, const QString& path) {
    std::ostringstream text;
    jl::writeEventsCsv(text, events);
    if (const auto error = saveText(path, text.str())) return failed(*error);
    return {true, {}, {path}};
}

namespace {

// The frames and events of a recorded run from `from` on, kept for the tables.
struct TableRows : jl::RecordTarget {
    double from = 0;
    std::vector<jl::Frame> frames;
    std::vector<jl::Event> events;
    bool frame(const jl::Frame& f) override {
        if (f.time < from - 1e-12) return true;
        frames.push_back(f);
        frames.back().events.clear();
        return true;
    }
    bool event(const jl::Event& e) override {
        if (e.time >= from) events.push_back(e);
        return true;
    }
};

}  // namespace

ExportResult Exporter::tables(const jl::Scene& scene, double from, double to, double every, const QString& directory) {
    if (!(every > 0) || !(to >= from))
        return failed(QObject::tr("The time range is empty: choose an end after the start and a positive interval."));
    if (!QDir().mkpath(directory)) return failed(QObject::tr("Could not make the folder %1.").arg(directory));
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) return failed(QObject::tr("The scene does not build."));
    // Recorded as the command line's export records it: the same rows.
    TableRows rows;
    rows.from = from;
    const jl::Recording run = jl::record(*built.simulation, to, jl::FrameGrid{from, every}, &rows);
    if (!run.failure.empty())
        return failed(
            QObject::tr("The run stopped at %1 s: %2").arg(run.time).arg(QString::fromStdString(run.failure)));
    std::ostringstream poses, energy, log;
    jl::writePosesCsv(poses, rows.frames);
    jl::writeEnergyCsv(energy, rows.frames);
    jl::writeEventsCsv(log, rows.events);
    ExportResult result{true, {}, {}};
    const std::pair<const char*, std::string> files[] = {
        {"poses.csv", poses.str()}, {"energy.csv", energy.str()}, {"events.csv", log.str()}};
    for (const auto& [name, text] : files) {
        const QString path = QDir(directory).filePath(name);
        if (const auto error = saveText(path, text)) return failed(*error);
        result.files << path;
    }
    return result;
}

QString Exporter::ffmpeg() { return QStandardPaths::findExecutable("ffmpeg"); }

QString Exporter::ffmpegMissing() {
    return QObject::tr(
        "Making a video needs ffmpeg, which is not installed on this computer. "
        "Install it (for example \"sudo apt install ffmpeg\") or export an image sequence "
        "instead and make the video elsewhere.");
}

ExportResult Exporter::video(const jl::Scene& scene, SequenceRequest request, const QString& videoPath) {
    const QString program = ffmpeg();
    if (program.isEmpty()) return failed(ffmpegMissing());
    QTemporaryDir pictures;
    if (!pictures.isValid()) return failed(QObject::tr("Could not make a temporary folder for the pictures."));
    request.directory = pictures.path();
    // H.264 wants even sizes (a painter's pictures are fitted to it too).
    request.size = QSize(request.size.width() / 2 * 2, request.size.height() / 2 * 2);
    const ExportResult frames = imageSequence(scene, request);
    if (!frames.ok) return frames;
    QStringList args{"-y",
                     "-loglevel",
                     "error",
                     "-framerate",
                     QString::number(request.fps),
                     "-i",
                     QDir(pictures.path()).filePath("frame_%05d.png")};
    if (QFileInfo(videoPath).suffix().compare("mp4", Qt::CaseInsensitive) == 0)
        args << "-c:v"
             << "libx264"
             << "-pix_fmt"
             << "yuv420p";
    args << videoPath;
    QProcess process;
    process.start(program, args);
    if (!process.waitForStarted()) return failed(QObject::tr("ffmpeg did not start: %1").arg(process.errorString()));
    process.waitForFinished(-1);
    if (process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0) {
        return failed(QObject::tr("ffmpeg could not make the video: %1")
                          .arg(QString::fromLocal8Bit(process.readAllStandardError()).trimmed()));
    }
    return {true, {}, {videoPath}};
}

}  // namespace jl::ui
