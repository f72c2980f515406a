// labels: ui
// Help teaches: First steps and Concepts open from the Help menu with their
// headings and every picture; each status-bar term that links to a concept
// finds its section; and the Controls sheet is ordered by task.
#include "ui_test_support.h"

#include <QDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

using namespace jl::ui;

namespace {

// The Help menu's action whose text, without its '&', is `text`.
QAction* helpAction(MainWindow& w, const QString& text) {
    for (QAction* menu : w.menuBar()->actions())
        if (menu->text().remove('&') == "Help" && menu->menu())
            for (QAction* a : menu->menu()->actions())
                if (a->text().remove('&') == text) return a;
    return nullptr;
}

// The document the Help page `text` shows once its menu entry is chosen.
QTextDocument* openPage(MainWindow& w, const QString& text) {
    QAction* a = helpAction(w, text);
    if (!a) return nullptr;
    a->trigger();
    for (QDialog* d : w.findChildren<QDialog*>())
        if (d->isVisible() && d->windowTitle() == text)
            if (auto* browser = d->findChild<QTextBrowser*>()) return browser->document();
    return nullptr;
}

QStringList headings(const QTextDocument* doc) {
    QStringList out;
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next())
        if (b.blockFormat().headingLevel() > 0) out << b.text().trimmed();
    return out;
}

// Every image's name, and every anchor's, in the document.
void imagesAndAnchors(const QTextDocument* doc, QStringList& images, QStringList& anchors) {
    for (QTextBlock b = doc->begin(); b.isValid(); b = b.next())
        for (auto it = b.begin(); !it.atEnd(); ++it) {
            const QTextCharFormat f = it.fragment().charFormat();
            if (f.isImageFormat()) images << f.toImageFormat().name();
            anchors << f.anchorNames();
        }
}

void checkImagesLoad(QTextDocument* doc) {
    QStringList images, anchors;
    imagesAndAnchors(doc, images, anchors);
    for (const QString& name : images) {
        const QVariant r = doc->resource(QTextDocument::ImageResource, QUrl(name));
        QVERIFY2(r.isValid(), qPrintable("no image " + name));
        const QImage image = r.canConvert<QImage>() ? r.value<QImage>() : QImage::fromData(r.toByteArray());
        QVERIFY2(!image.isNull() && image.width() > 0 && image.height() > 0, qPrintable("empty image " + name));
    }
}

}  // namespace

class HelpPagesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void firstStepsWalksThroughTheSession() {
        MainWindow w(jl::test::quietWindow());
        QTextDocument* doc = openPage(w, "First steps");
        QVERIFY(doc);
        const QStringList h = headings(doc);
        for (const char* step :
             {"Open a lesson", "Play and pause", "Step one frame", "Slow motion", "Scrub back to an event",
              "Drag a block", "Edit the ladder, and undo", "Save the scene"})
            QVERIFY2(h.filter(step).size() == 1, qPrintable("no heading " + QString(step)));
        checkImagesLoad(doc);
    }

    void conceptsShowEveryPicture() {
        MainWindow w(jl::test::quietWindow());
        QTextDocument* doc = openPage(w, "Concepts");
        QVERIFY(doc);
        const QStringList h = headings(doc);
        for (const char* c : {"The hinge", "Lock", "Fold", "The flip-flop", "The energy books", "The gap"})
            QVERIFY2(h.contains(c), qPrintable("no heading " + QString(c)));
        QStringList images, anchors;
        imagesAndAnchors(doc, images, anchors);
        QCOMPARE(images.size(), 6);
        checkImagesLoad(doc);
    }

    void statusBarTermsFindTheirConcept() {
        MainWindow w(jl::test::quietWindow());
        QStringList linked;
        for (QLabel* l : w.statusBar()->findChildren<QLabel*>())
            if (l->property("concept").isValid()) linked << l->property("concept").toString();
        for (const char* term : {"real-time-factor", "balance", "gap", "errors"})
            QVERIFY2(linked.contains(term), qPrintable("no status-bar term links to " + QString(term)));
        QTextDocument* doc = openPage(w, "Concepts");
        QVERIFY(doc);
        QStringList images, anchors;
        imagesAndAnchors(doc, images, anchors);
        for (const QString& a : linked) QVERIFY2(anchors.contains(a), qPrintable("Concepts has no #" + a));
    }

    void aClickOnTheGapOpensConcepts() {
        MainWindow w(jl::test::quietWindow());
        auto* gap = w.findChild<QLabel*>("residual");
        QVERIFY(gap);
        QTest::mouseClick(gap, Qt::LeftButton);
        auto* page = w.findChild<QDialog*>("helpPage_concepts");
        QVERIFY(page && page->isVisible());
    }

    void controlsSheetIsOrderedByTask() {
        MainWindow w(jl::test::quietWindow());
        QAction* controls = helpAction(w, "Controls");
        QVERIFY(controls);
        controls->trigger();
        auto* box = w.findChild<QMessageBox*>("controlsHelp");
        QVERIFY(box);
        QStringList sections;
        static const QRegularExpression h3("<h3>([^<]*)</h3>");
        for (auto m = h3.globalMatch(box->text()); m.hasNext();) sections << m.next().captured(1);
        QCOMPARE(sections.mid(0, 5), (QStringList{"Watching", "Scrubbing", "Editing", "Files", "Presentation"}));
        // Each task holds its keys: Space plays, Ctrl+Z undoes, Ctrl+S saves, F5 presents.
        const QString text = box->text();
        auto sectionOf = [&](const QString& key) {
            const int at = text.indexOf("<b>" + key + "</b>");
            return at < 0 ? QString() : sections.value(text.left(at).count("<h3>") - 1);
        };
        QCOMPARE(sectionOf("Space"), QString("Watching"));
        QCOMPARE(sectionOf("Ctrl+Z"), QString("Editing"));
        QCOMPARE(sectionOf("Ctrl+S"), QString("Files"));
        QCOMPARE(sectionOf("F5"), QString("Presentation"));
    }
};

QTEST_MAIN(HelpPagesTest)
#include "test_help_pages.moc"
