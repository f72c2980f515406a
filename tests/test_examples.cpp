// labels: io;physics
// Every example loads, has a title and a description, and runs for a second
// without a failure, with its energy books balanced and its pins closed.
#include "tests/scene_run.h"

#include <QtTest>
#include <filesystem>

using namespace jl;
using namespace jl::test;

class ExamplesTest : public QObject {
    Q_OBJECT
private slots:
    void everyExampleLoadsAndRuns_data() {
        QTest::addColumn<QString>("path");
        int n = 0;
        for (const auto& e : std::filesystem::directory_iterator(std::string(JL_SOURCE_DIR) + "/examples"))
            if (e.path().extension() == ".yaml") {
                QTest::newRow(e.path().filename().c_str()) << QString::fromStdString(e.path().string());
                ++n;
            }
        QVERIFY(n >= 8);
    }

    void everyExampleLoadsAndRuns() {
        QFETCH(QString, path);
        SceneLoad load = loadScene(path.toStdString());
        for (const Diagnostic& d : load.errors) qWarning("%s", d.format().c_str());
        QVERIFY(load.scene);
        QVERIFY(!load.scene->title.empty());
        QVERIFY(load.scene->description.size() > 80);
        auto built = Simulation::build(*load.scene);
        QVERIFY(built.simulation);
        const Run r = runUntil(*built.simulation, 1.0);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY2(r.worstBalance < 1e-5, qPrintable(QString::number(r.worstBalance)));
        QVERIFY2(r.worstResidual <= load.scene->solver.projectionTolerance * 1.0000001,
                 qPrintable(QString::number(r.worstResidual)));
        QVERIFY(r.impactLossNeverFell);
    }
};

QTEST_GUILESS_MAIN(ExamplesTest)
#include "test_examples.moc"
