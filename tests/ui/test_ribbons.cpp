// labels: ui
// The toy's ribbons as a class sees them: on the classic cascade, at the
// default camera in a 1440 x 900 window, each block's face toward the eye
// shows either the outer pair or the middle ribbon (pixels of the two
// ribbon colours counted inside the face), alternating down the ladder, the
// top block with two, before the turn and after the cascade; and at a
// flip-flop's instant the ribbons' wrap moves to the blocks' other end.
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "ui/play/sim_controller.h"
#include "ui/view3d/block_shapes.h"
#include "ui/view3d/ladder_view.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

#include <QMatrix4x4>
#include <QPolygonF>
#include <QTemporaryDir>
#include <QVector3D>
#include <Qt3DRender/QCamera>
#include <QtTest>

#include <cmath>
#include <fstream>

using namespace jl::ui;

namespace {

const QColor kOuter(30, 60, 230), kMiddle(230, 30, 30);

// The classic cascade with the outer pair blue and the middle ribbon red.
jl::Scene classicInTwoColours() {
    auto loaded = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
    if (!loaded.scene) qFatal("classic.yaml does not load");
    jl::Scene s = *loaded.scene;
    s.ladder->ribbons.color = {30, 60, 230};
    s.ladder->ribbons.centralColor = {230, 30, 30};
    return s;
}

bool blue(QRgb c) { return qBlue(c) > qRed(c) + 60 && qBlue(c) > qGreen(c) + 40; }
bool red(QRgb c) { return qRed(c) > qBlue(c) + 60 && qRed(c) > qGreen(c) + 60; }

enum class Shows { Outer, Middle, Unclear };

struct Face {
    Shows shows = Shows::Unclear;
    int outer = 0, middle = 0;  // pixels of each colour inside the face
};

// What the side face of block i toward the eye shows in the picture: the
// face's middle 70 % along the block (clear of the wraps at its ends),
// projected with the view's camera, its pixels of each ribbon colour counted.
Face faceTowardTheEye(LadderView* view, const QImage& image, const jl::Pose& pose, const BlockShape& shape) {
    const QMatrix4x4 vp = view->camera()->projectionMatrix() * view->camera()->viewMatrix();
    const QVector3D eye = view->camera()->position();
    const float c = float(std::cos(pose.angle)), s = float(std::sin(pose.angle));
    const auto world = [&](float u, float v, float z) {
        return QVector3D(float(pose.position.x()) + c * u - s * v, float(pose.position.y()) + s * u + c * v, z);
    };
    float side = 1;
    {
        const QVector3D n(c, s, 0), centre = world(shape.across / 2, 0, 0);
        if (QVector3D::dotProduct(n, eye - centre) < 0) side = -1;
    }
    QPolygonF polygon;
    const float u = side * shape.across / 2, v = 0.35f * shape.along, w = shape.out / 2;
    for (const auto& [vv, z] : {std::pair{-v, -w}, {v, -w}, {v, w}, {-v, w}}) {
        const QVector4D clip = vp * QVector4D(world(u, vv, z), 1);
        const double x = (clip.x() / clip.w() + 1) / 2 * image.width();
        const double y = (1 - clip.y() / clip.w()) / 2 * image.height();
        polygon << QPointF(x, y);
    }
    Face f;
    const QRect box = polygon.boundingRect().toAlignedRect().intersected(image.rect());
    for (int y = box.top(); y <= box.bottom(); ++y)
        for (int x = box.left(); x <= box.right(); ++x) {
            if (!polygon.containsPoint(QPointF(x + 0.5, y + 0.5), Qt::OddEvenFill)) continue;
            const QRgb p = image.pixel(x, y);
            f.outer += blue(p);
            f.middle += red(p);
        }
    if (f.outer > 40 && f.outer > 4 * f.middle) f.shows = Shows::Outer;
    if (f.middle > 40 && f.middle > 4 * f.outer) f.shows = Shows::Middle;
    return f;
}

QString describe(const std::vector<Face>& faces) {
    QStringList s;
    for (const Face& f : faces)
        s << QString("%1 (%2 blue, %3 red)")
                 .arg(f.shows == Shows::Outer    ? "outer"
                      : f.shows == Shows::Middle ? "middle"
                                                 : "?")
                 .arg(f.outer)
                 .arg(f.middle);
    return s.join("; ");
}

}  // namespace

class RibbonsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void everyFaceShowsTheOuterPairOrTheMiddleRibbonAlternately() {
        MainWindow w{jl::test::quietWindow()};
        w.resize(1440, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        SimController* sim = w.controller();
        const jl::Scene scene = classicInTwoColours();
        const auto before = jl::test::loadsSoFar(sim);
        w.document()->reset(scene, QString());
        QVERIFY(jl::test::loadedAfter(sim, before));
        const std::vector<BlockShape> shapes = blockShapes(scene);
        for (const double t : {0.0, 2.5}) {
            if (t > 0) {
                sim->seek(t);
                QVERIFY(jl::test::waitForStatus(sim, [t](const SimStatus& s) {
                    return s.frame && std::abs(s.frame->time - t) < 1e-6 && s.seekingTo < 0;
                }));
            }
            QTest::qWait(300);
            const QImage image = jl::test::captureView(w.ladderView()).convertToFormat(QImage::Format_RGB32);
            QVERIFY(!image.isNull());
            const auto frame = sim->status()->frame;
            std::vector<Face> faces;
            for (size_t i = 0; i < frame->poses.size(); ++i)
                faces.push_back(faceTowardTheEye(w.ladderView(), image, frame->poses[i], shapes[i]));
            qInfo("t = %.1f s: %s", t, qPrintable(describe(faces)));
            for (size_t i = 0; i < faces.size(); ++i) {
                QVERIFY2(faces[i].shows != Shows::Unclear,
                         qPrintable(QString("t = %1 s: block %2 shows neither kind clearly").arg(t).arg(i)));
                if (i > 0)
                    QVERIFY2(faces[i].shows != faces[i - 1].shows,
                             qPrintable(QString("t = %1 s: blocks %2 and %3 show the same").arg(t).arg(i - 1).arg(i)));
            }
            if (t == 0) QVERIFY2(faces[0].shows == Shows::Outer, "the top block starts with the outer pair");
        }
    }

    // Hinge 1 flips (block 1 over block 0's far end): just before, the wrap
    // of its ribbons is at one end of the blocks; just after, at the other,
    // a block's length away.
    void aFlipMovesTheWrapToTheOtherEndAtItsInstant() {
        const jl::Scene scene = classicInTwoColours();
        auto sim = jl::Simulation::build(scene).simulation;
        QVERIFY(sim);
        double flip = -1;
        while (flip < 0 && sim->time() < 2.5) {
            QVERIFY(sim->advanceToNextEvent(2.5) || sim->time() >= 2.5);
            for (const jl::Event& e : sim->takeEvents())
                if (e.kind == jl::EventKind::FlipFlop && e.hinge == 1 && flip < 0) flip = e.time;
        }
        QVERIFY2(flip > 0, "hinge 1 never flips");
        const auto wrapAt = [&](double t) {
            auto s = jl::Simulation::build(scene).simulation;
            s->advanceExactlyTo(t);
            const jl::Frame f = s->frame();
            return f.ribbons.front().points[2];  // hinge 1's outer pair: the point where it crosses
        };
        const double L = scene.ladder->block.length;
        const jl::Vec2 before = wrapAt(flip - 1e-4), after = wrapAt(flip + 1e-4);
        qInfo("hinge 1 flips at %.9f s; the wrap moves %.4f m (a block is %.3f m)", flip, (after - before).norm(), L);
        QVERIFY(std::abs((after - before).norm() - L) < 0.1 * L);
    }
};

QTEST_MAIN(RibbonsTest)
#include "test_ribbons.moc"
