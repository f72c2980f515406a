// labels: ui
// The viewer's camera: framing a long ladder, orbiting about the target,
// walking (eye and target together) and looking around from the eye.
#include "ui/view_camera.h"

#include <QtTest>
#include <cmath>
#include <numbers>

using namespace jlui;

class ViewCameraTest : public QObject {
    Q_OBJECT
private slots:
    void aShortLadderKeepsTheScenesView() {
        ViewCamera c;
        jl::ViewSpec v;  // target (0, -0.15), distance 0.8, yaw 0, pitch 10
        c.reset(v, 0.36);
        QCOMPARE(c.distance(), 0.8f);
        const QVector3D eye = c.eye();
        QVERIFY(qAbs(eye.x()) < 1e-6f);
        QVERIFY(qFuzzyCompare(eye.y(), float(-0.15 + 0.8 * std::sin(10 * std::numbers::pi / 180))));
    }

    void aLongLadderIsFramedWhole() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 60.0);  // 1000 blocks of 60 mm
        // 40 degrees of view must span the 60 m with a margin.
        const float visible = 2 * c.distance() * std::tan(float(20 * std::numbers::pi / 180));
        QVERIFY(visible > 60.0f && visible < 75.0f);
    }

    void orbitingKeepsTheDistanceToTheTarget() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 0.36);
        const QVector3D target(0, -0.15f, 0);
        c.orbit(90, 20);
        QVERIFY(qFuzzyCompare((c.eye() - target).length(), 0.8f));
        QVERIFY(c.eye().x() > 0.5f);  // a quarter turn: now looking from +x
        c.orbit(0, 500);              // pitch stops short of straight down (85 degrees)
        const float height = c.eye().y() - target.y();
        QVERIFY2(height > 0.79f && height < 0.8f * std::sin(86.0f * 3.14159265f / 180), qPrintable(QString::number(height)));
        QVERIFY(std::abs(c.eye().x() - target.x()) + std::abs(c.eye().z() - target.z()) > 0.05f);
    }

    void walkingMovesTheEyeLevelAndLookingAroundKeepsIt() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 0.36);
        const QVector3D before = c.eye();
        c.walk(1.0f, 0, 0);  // a metre forward, toward the ladder (-z), level
        const QVector3D after = c.eye();
        QVERIFY(qFuzzyCompare(after.z(), before.z() - 1.0f));
        QVERIFY(qFuzzyCompare(after.y(), before.y()));
        c.lookAround(45, 0);
        QVERIFY((c.eye() - after).length() < 1e-5f);
    }
};

QTEST_MAIN(ViewCameraTest)
#include "test_view_camera.moc"
