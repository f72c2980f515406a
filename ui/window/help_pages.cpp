#include "ui/window/help_pages.h"

#include <QDialog>
#include <QEvent>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

// The pages' resource lives in a static library: the linker keeps it only
// when something names it.
static void registerHelpResource() { Q_INIT_RESOURCE(help); }

namespace jl::ui {

namespace {

// Opens the Concepts page at its section when the label it watches is clicked.
class ConceptClick : public QObject {
public:
    ConceptClick(QLabel* label, QString anchor) : QObject(label), label_(label), anchor_(std::move(anchor)) {}

protected:
    bool eventFilter(QObject* watched, QEvent* e) override {
        if (watched == label_ && e->type() == QEvent::MouseButtonRelease &&
            static_cast<QMouseEvent*>(e)->button() == Qt::LeftButton)
            showHelpPage(label_->window(), "concepts", anchor_);
        return false;
    }

private:
    QLabel* label_;
    QString anchor_;
};

QString pageTitle(const QString& page) {
    return page == "concepts" ? QObject::tr("Concepts") : QObject::tr("First steps");
}

}  // namespace

void showHelpPage(QWidget* window, const QString& page, const QString& anchor) {
    registerHelpResource();
    const QString name = "helpPage_" + page;
    auto* dialog = window->findChild<QDialog*>(name);
    if (!dialog) {
        dialog = new QDialog(window);
        dialog->setObjectName(name);
        dialog->setWindowTitle(pageTitle(page));
        dialog->setModal(false);
        auto* browser = new QTextBrowser(dialog);
        browser->setObjectName("helpBrowser");
        // Links between the pages stay inside the window.
        browser->setOpenLinks(true);
        browser->setSource(QUrl("qrc:/help/" + page + ".html"));
        auto* layout = new QVBoxLayout(dialog);
        layout->setContentsMargins(0, 0, 0, 0);
        layout->addWidget(browser);
        dialog->resize(640, 720);
    }
    if (!anchor.isEmpty()) dialog->findChild<QTextBrowser*>("helpBrowser")->scrollToAnchor(anchor);
    dialog->show();
    dialog->raise();
    dialog->activateWindow();
}

void linkToConcept(QLabel* label, const QString& anchor) {
    label->setProperty("concept", anchor);
    label->setToolTip(label->toolTip() + QObject::tr("\nClick to read about it in Help > Concepts."));
    label->setCursor(Qt::PointingHandCursor);
    label->installEventFilter(new ConceptClick(label, anchor));
}

void addHelpPages(QMenu* help, QWidget* window) {
    help->addAction(QObject::tr("&First steps"), window, [window] { showHelpPage(window, "first-steps"); })
        ->setObjectName("firstStepsAction");
    help->addAction(QObject::tr("C&oncepts"), window, [window] { showHelpPage(window, "concepts"); })
        ->setObjectName("conceptsAction");
}

void linkStatusBarToConcepts(QWidget* window) {
    const std::pair<const char*, const char*> terms[] = {
        {"rate", "real-time-factor"}, {"energy", "balance"}, {"residual", "gap"}, {"warning", "errors"}};
    for (const auto& [name, anchor] : terms)
        if (auto* label = window->findChild<QLabel*>(name)) linkToConcept(label, anchor);
}

}  // namespace jl::ui
