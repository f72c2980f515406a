#include "ui/teaching/lessons.h"

#include "jl/scene/scene_io.h"
#include "ui/window/presentation_mode.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace jl::ui {

namespace {

// The teaching order of docs/teaching.md; files not named here come after.
const char* const kTeachingOrder[] = {"classic",
                                      "wrong-way",
                                      "one-hinge",
                                      "back-and-forth",
                                      "two-ripples",
                                      "pushed-down-pulled-up",
                                      "heavy-middle",
                                      "long-ladder",
                                      "dropped-on-a-table",
                                      "pendulum",
                                      "particles-and-springs",
                                      "falling-chain"};

int rank(const QString& baseName) {
    const auto it = std::find(std::begin(kTeachingOrder), std::end(kTeachingOrder), baseName.toStdString());
    return int(it - std::begin(kTeachingOrder));
}

// `path` in full when it holds scenes, else empty.
QString withScenes(const QString& path) {
    const QDir d(path);
    if (path.isEmpty() || !d.exists() || d.entryList({"*.yaml"}, QDir::Files).isEmpty()) return {};
    return d.canonicalPath();
}

}  // namespace

QString lessonsDirectoryBeside(const QString& programDirectory) {
    // Only the layout around the program: a path compiled in would name the
    // checkout it was built from, whose lessons a copied program would list.
    if (programDirectory.isEmpty()) return {};
    return withScenes(programDirectory + "/../share/jacobs-ladder/examples");
}

QString lessonsDirectory() {
    if (const QString env = withScenes(qEnvironmentVariable("JL_EXAMPLES")); !env.isEmpty()) return env;
    return lessonsDirectoryBeside(QCoreApplication::applicationDirPath());
}

bool isLesson(const QString& path) {
    const QString lessons = lessonsDirectory();
    return !path.isEmpty() && !lessons.isEmpty() && QFileInfo(path).absoluteDir().canonicalPath() == lessons;
}

QString saveAsProposal(const QString& path) {
    if (!isLesson(path)) return path;
    // A documents folder that is not there (a bare account) is not made: home then.
    QDir mine(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
    if (!mine.exists()) mine = QDir::home();
    return mine.filePath(QFileInfo(path).fileName());
}

std::vector<Lesson> findLessons(const QString& directory) {
    std::vector<Lesson> out;
    if (directory.isEmpty()) return out;
    const QDir dir(directory);
    for (const QFileInfo& f : dir.entryInfoList({"*.yaml"}, QDir::Files, QDir::Name)) {
        const jl::SceneLoad load = jl::loadScene(f.absoluteFilePath().toStdString());
        if (!load.scene) continue;  // a broken example is not a lesson
        Lesson l{f.absoluteFilePath(), QString::fromStdString(load.scene->title),
                 QString::fromStdString(load.scene->description).trimmed()};
        if (l.title.isEmpty()) l.title = f.completeBaseName();
        out.push_back(std::move(l));
    }
    std::stable_sort(out.begin(), out.end(), [](const Lesson& a, const Lesson& b) {
        return rank(QFileInfo(a.path).completeBaseName()) < rank(QFileInfo(b.path).completeBaseName());
    });
    return out;
}

LessonsMenu::LessonsMenu(const std::vector<Lesson>& lessons, QWidget* parent) : QMenu(tr("&Lessons"), parent) {
    setObjectName("lessonsMenu");
    setToolTipsVisible(true);
    for (const Lesson& l : lessons) {
        QAction* a = addAction(l.title);
        a->setToolTip(l.description);
        a->setStatusTip(l.description);
        a->setData(l.path);
        connect(a, &QAction::triggered, this, [this, path = l.path] { emit openRequested(path); });
    }
    if (lessons.empty()) addAction(tr("(no example scenes found)"))->setEnabled(false);
}

LessonPanel::LessonPanel(QWidget* parent) : QWidget(parent) {
    setObjectName("lessonPanel");
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    text_ = new QTextBrowser(this);
    text_->setObjectName("lessonText");
    text_->setOpenLinks(false);
    box->addWidget(text_);
    connect(text_, &QTextBrowser::anchorClicked, this, [this](const QUrl& url) {
        if (url.toString() == "edit") emit editTextRequested();
    });
}

void LessonPanel::showScene(const jl::Scene& scene, bool edited) {
    const QString title = QString::fromStdString(scene.title).toHtmlEscaped();
    QString description = QString::fromStdString(scene.description).trimmed().toHtmlEscaped();
    description.replace("\n\n", "</p><p>");
    if (title.isEmpty() && description.isEmpty()) {
        text_->setHtml(
            tr("<p><i>This scene has no title or description. Add them in the scene file "
               "(<tt>title:</tt> and <tt>description:</tt>) to make it a lesson.</i></p>"));
        return;
    }
    // A lesson's words describe the scene as it was written: after an edit
    // they may describe another ladder (six blocks, over ten on screen).
    const QString note =
        edited ? tr("<p style=\"background:#fff4c2\"><i>Edited: the scene has changed since these words were "
                    "written, and they may no longer describe it.</i> <a href=\"edit\">Edit the title and "
                    "description...</a></p>")
               : QString();
    text_->setHtml(QString("%1<h3>%2</h3><p>%3</p>").arg(note, title, description));
}

void LessonPanel::setLarge(bool large) {
    QFont f = text_->font();
    f.setPointSizeF(large ? 18 * presentationSize(this) : QFont().pointSizeF());
    text_->setFont(f);
}

QString LessonPanel::text() const { return text_->toPlainText(); }

}  // namespace jl::ui
