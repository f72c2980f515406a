// Exports of a run for slides and reports: a picture of the 3-D view or of the
// side view, a sequence of PNG frames over a time range (drawn by either), a
// video made from them by ffmpeg, the event log and the tables as CSV.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"
#include "ui/teaching/side_view.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

namespace jl::ui {

class LadderView;

struct ExportResult {
    bool ok = false;
    QString error;      // in words, when !ok
    QStringList files;  // what was written
};

// Turns a frame into a picture (the 3-D view's: viewPainter, ui/view3d/view_capture.h).
using FramePainter = std::function<QImage(const jl::Frame&)>;

struct SequenceRequest {
    double from = 0, to = 1;                            // s, both ends included when on the grid
    double fps = 30;                                    // pictures per simulated second
    QSize size{1280, 720};                              // of the pictures; a painter's are scaled whole into it
    QString directory;                                  // frame_00000.png, frame_00001.png, ...
    SideViewOptions look{};                             // for the side view, when no painter is given
    FramePainter painter;                               // optional: draws each frame instead of the side view
    std::function<bool(int done, int total)> progress;  // false cancels
};

class Exporter {
public:
    // The 3-D view as it is on screen, at its size (ui/view3d/view_capture.h).
    static ExportResult viewPicture(LadderView* view, const QString& path);
    // The side view of one frame.
    static ExportResult sideViewPicture(const jl::Scene& scene, const jl::Frame& frame, const QSize& size,
                                        const SideViewOptions& look, const QString& path);

    // How many pictures a range makes: one at from, then every 1/fps up to to.
    static int frameCount(double from, double to, double fps);
    // Re-runs the scene (its script and recorded drags: the same run as on
    // screen, deterministically) without a display and saves each picture.
    static ExportResult imageSequence(const jl::Scene& scene, const SequenceRequest& request);

    // The event log as CSV (jl/sim/event_csv.h), written atomically.
    static ExportResult eventsCsv(const std::vector<jl::Event>& events, const QString& path);
    // Re-runs the scene and writes poses.csv, energy.csv and events.csv
    // (jl/sim/frame_csv.h, jl/sim/event_csv.h) into `directory`, recorded as
    // `jladder export` records them (jl/sim/recording.h): a frame at the first
    // step at or after each multiple of `every` from `from` on, to exactly
    // `to`, and the events in between.
    static ExportResult tables(const jl::Scene& scene, double from, double to, double every, const QString& directory);

    // Where ffmpeg is, or empty when it is not installed; what to tell the user then.
    static QString ffmpeg();
    static QString ffmpegMissing();
    // The sequence, then ffmpeg (H.264 in MP4, or whatever the suffix asks for).
    static ExportResult video(const jl::Scene& scene, SequenceRequest request, const QString& videoPath);
};

}  // namespace jl::ui
