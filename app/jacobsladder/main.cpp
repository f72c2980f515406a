// The desktop program: jacobsladder [scene.yaml]
#include "ui/ladder_view.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/sim_controller.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QScreen>
#include <QTimer>

#include <cstdio>

namespace {

// Hidden option for documentation: grab the screen after a while, save it, quit.
void scheduleScreenshot(jl::ui::MainWindow& window, const QString& file, double afterSeconds) {
    QTimer::singleShot(int(afterSeconds * 1000), &window, [&window, file] {
        QScreen* screen = window.screen();
        const QPixmap shot = screen->grabWindow(0, window.frameGeometry().x(), window.frameGeometry().y(),
                                                window.frameGeometry().width(), window.frameGeometry().height());
        shot.save(file);
        window.close();
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
    for (QCommandLineOption* o : {&screenshot, &after, &seek, &orbit, &lessons})
        o->setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOptions({screenshot, after, play, seek, orbit, lessons});
    parser.process(app);
    if (parser.isSet(lessons)) {
        std::printf("%s\n", qPrintable(jl::ui::lessonsDirectory()));
        return jl::ui::lessonsDirectory().isEmpty() ? 1 : 0;
    }

    jl::ui::MainWindow window;
    window.show();
    if (!parser.positionalArguments().isEmpty()) window.openFile(parser.positionalArguments().first());
    else window.offerRecovery();
    if (parser.isSet(orbit)) window.ladderView()->orbit(parser.value(orbit).toFloat(), 0);
    if (parser.isSet(seek)) window.controller()->seek(parser.value(seek).toDouble());
    if (parser.isSet(play)) window.controller()->play();
    if (parser.isSet(screenshot)) scheduleScreenshot(window, parser.value(screenshot), parser.value(after).toDouble());
    return app.exec();
}
