// labels: ui
// The 3-D view exported as it is drawn: a picture from Teach > Export (the
// view's size, the blocks' wood in it), and the pictures a video of it is
// made from, one per frame of the run at the times asked for, at the size
// the dialog asks for.
#include "jl/sim/simulation.h"
#include "ui/teaching/exporter.h"
#include "ui/teaching/teaching_docks.h"
#include "ui/view3d/view_capture.h"
#include "ui_test_support.h"

#include <QFileDialog>
#include <QMenu>
#include <QTemporaryDir>
#include <QtTest>

using namespace jl::ui;

namespace {

const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");
const QColor kWood(200, 162, 107);  // #c8a26b, the classic file's block colour

// Pixels of the blocks' wood in `image`.
int woodPixels(const QImage& image) {
    int n = 0;
    for (int y = 0; y < image.height(); y += 2)
        for (int x = 0; x < image.width(); x += 2) n += jl::test::woodColoured(image.pixelColor(x, y), kWood);
    return n;
}

// The view (553 x 499 here) scaled into 640 x 360: 983 to 1,251 wood pixels
// measured (every other one counted), 2,496 at its own size.
constexpr int kWoodAt640 = 500;
// The view's size in the pixels it is drawn with.
QSize drawnSize(LadderView* view) { return view->size() * view->devicePixelRatio(); }

QAction* exportAction(MainWindow& w, const QString& text) {
    auto* menu = w.teaching()->teachMenu()->findChild<QMenu*>("exportMenu");
    if (menu)
        for (QAction* a : menu->actions())
            if (a->text() == text) return a;
    return nullptr;
}

// Saves to `path` in the next file dialog.
void saveInNextFileDialog(const QString& path) {
    jl::test::answerNextModal([=](QWidget* modal) {
        auto* dialog = qobject_cast<QFileDialog*>(modal);
        if (!dialog) return false;
        dialog->selectFile(path);
        QMetaObject::invokeMethod(dialog, "accept");
        return true;
    });
}

}  // namespace

class ViewExportTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void thePictureIsTheViewAtItsSizeWithTheBlocksInIt() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        QTest::qWait(300);  // a few rendered frames with the poses in place
        QTemporaryDir dir;
        const QString path = dir.filePath("ladder.png");
        QAction* picture = exportAction(w, "3-D view as a p&icture...");
        QVERIFY2(picture, "no Teach > Export > 3-D view as a picture");
        saveInNextFileDialog(path);
        picture->trigger();
        const QImage png(path);
        QVERIFY2(!png.isNull(), "no picture written");
        QCOMPARE(png.size(), drawnSize(w.ladderView()));
        QVERIFY(!png.hasAlphaChannel());
        // Six blocks of 6 cm by 4.5 cm fill well over a thousand pixels (every
        // other one counted); the room around them has no wood.
        const int wood = woodPixels(png);
        QVERIFY2(wood > 1000, qPrintable(QString("%1 wood pixels").arg(wood)));
        QVERIFY2(wood < png.width() * png.height() / 4 / 4, qPrintable(QString("%1 wood pixels").arg(wood)));
    }

    // Without ffmpeg (not a dependency), what the video writer would be
    // handed: the sequence the video export makes (Exporter::video).
    void theVideosPicturesAreTheViewsFramesAtTheTimesAsked() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        w.controller()->pause();
        QTemporaryDir dir;
        SequenceRequest r;
        r.from = 0;
        r.to = 1.0;
        r.fps = 5;
        r.size = QSize(640, 360);  // not the view's size, nor its shape
        r.directory = dir.filePath("frames");
        std::vector<double> times;
        int withRibbons = 0;
        const FramePainter paint = viewPainter(w.ladderView());
        r.painter = [&](const jl::Frame& f) {
            times.push_back(f.time);
            withRibbons += f.ribbons.size() == 2 * 5;  // two per hinge, to draw as the view does on screen
            return paint(f);
        };
        const jl::Scene scene = w.document()->scene();
        const ExportResult made = Exporter::imageSequence(scene, r);
        QVERIFY2(made.ok, qPrintable(made.error));
        QCOMPARE(int(made.files.size()), 6);
        for (int i = 0; i < 6; ++i) QCOMPARE(times[size_t(i)], 0.2 * i);
        QCOMPARE(withRibbons, 6);
        std::vector<QImage> pictures;
        for (const QString& file : made.files) {
            pictures.emplace_back(file);
            QCOMPARE(pictures.back().size(), r.size);
            QVERIFY2(woodPixels(pictures.back()) > kWoodAt640, qPrintable(file));
        }
        // The ladder moves: the top block turns from 0.2 s and the flips run down.
        QVERIFY(pictures.front() != pictures.back());
        if (!Exporter::ffmpeg().isEmpty()) {
            r.painter = paint;
            const ExportResult video = Exporter::video(scene, r, dir.filePath("ladder.mp4"));
            QVERIFY2(video.ok, qPrintable(video.error));
            QVERIFY(QFileInfo(dir.filePath("ladder.mp4")).size() > 0);
        }
    }
};

QTEST_MAIN(ViewExportTest)
#include "test_view_export.moc"
