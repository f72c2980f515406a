// The desktop program: jacobsladder [scene.yaml]
#include "ui/design/design_map.h"
#include "ui/play/sim_controller.h"
#include "ui/teaching/lessons.h"
#include "ui/view3d/ladder_view.h"
#include "ui/window/main_window.h"
#include "ui/window/presentation_mode.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QScreen>
#include <QTimer>

#include <cstdio>
#include <functional>

namespace {

// Hidden option for documentation (tools/screenshots.sh): grab what the
// screen shows of `shown` (the window, or a dialog of it) after a while,
// save it, quit. The screen, not the widget: QWidget::grab misses the 3-D view.
void scheduleScreenshot(jl::ui::MainWindow& window, std::function<QWidget*()> shown, const QString& file,
                        double afterSeconds) {
    QTimer::singleShot(int(afterSeconds * 1000), &window, [&window, shown, file] {
        QWidget* w = shown();
        const QRect r = w->frameGeometry();
        const QPixmap shot = w->screen()->grabWindow(0, r.x(), r.y(), r.width(), r.height());
        if (!shot.save(file)) std::fprintf(stderr, "jacobsladder: could not write %s\n", qPrintable(file));
        window.close();
        QApplication::quit();
    });
}

}  // namespace

int main(int argc, char** argv) {
    // Qt3D's RHI renderer crashes without a GPU; the OpenGL one works everywhere we run.
    if (qEnvironmentVariableIsEmpty("QT3D_RENDERER")) qputenv("QT3D_RENDERER", "opengl");
    QApplication app(argc, argv);
    QApplication::setOrganizationName("JacobsLadderStudio");
    QApplication::setApplicationName("Jacob's Ladder Studio");
    QApplication::setApplicationVersion(JL_VERSION);

    QCommandLineParser parser;
    parser.setApplicationDescription("Build, simulate and teach with a virtual Jacob's ladder.");
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument("scene", "A scene file to open (.yaml).", "[scene.yaml]");
    QCommandLineOption screenshot("screenshot", "Save a picture of the window to FILE, then quit.", "FILE");
    QCommandLineOption after("after", "Seconds to wait before --screenshot.", "SECONDS", "3");
    QCommandLineOption play("play", "Start playing at once.");
    QCommandLineOption seek("seek", "Simulate up to SECONDS and show that moment.", "SECONDS");
    QCommandLineOption orbit("orbit", "Turn the view by DEGREES about the ladder.", "DEGREES");
    QCommandLineOption lessons("lessons-directory", "Print where the lessons (the examples) are found, then quit.");
    QCommandLineOption designMap("design-map", "Open the design map (--screenshot then shows it).");
    QCommandLineOption present("present", "Start in presentation mode.");
    for (QCommandLineOption* o : {&screenshot, &after, &seek, &orbit, &lessons, &designMap, &present})
        o->setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOptions({screenshot, after, play, seek, orbit, lessons, designMap, present});
    parser.process(app);
    if (parser.isSet(lessons)) {
        std::printf("%s\n", qPrintable(jl::ui::lessonsDirectory()));
        return jl::ui::lessonsDirectory().isEmpty() ? 1 : 0;
    }

    jl::ui::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty())
        window.openFile(parser.positionalArguments().first());
    else
        window.offerRecovery();
    if (parser.isSet(orbit)) window.ladderView()->orbit(parser.value(orbit).toFloat(), 0);
    if (parser.isSet(seek)) window.controller()->seek(parser.value(seek).toDouble());
    if (parser.isSet(play)) window.controller()->play();
    if (parser.isSet(present)) window.presentation()->setActive(true);
    if (parser.isSet(designMap)) {
        window.showDesignMap();
        window.designMap()->compute();
    }
    if (parser.isSet(screenshot)) {
        const bool map = parser.isSet(designMap);
        scheduleScreenshot(
            window,
            [&window, map]() -> QWidget* {
                if (map && window.designMap()) return window.designMap();
                return &window;
            },
            parser.value(screenshot), parser.value(after).toDouble());
    }
    return app.exec();
}
