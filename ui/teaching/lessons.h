// Lessons: the example scenes with their titles and descriptions, a menu
// that opens them, and a panel that shows the open scene's description.
#pragma once

#include "jl/scene/scene.h"

#include <QMenu>
#include <QString>
#include <QWidget>

#include <vector>

class QTextBrowser;

namespace jl::ui {

struct Lesson {
    QString path;         // the scene file
    QString title;        // its `title`, else the file name
    QString description;  // its `description`
};

// Where the example scenes are: $JL_EXAMPLES, else beside the program, in
// share/jacobs-ladder/examples next to its bin/ (an install, or the build
// tree, which is laid out as one); else none.
QString lessonsDirectory();
// The lessons folder a program in `programDirectory` finds beside it, or empty.
QString lessonsDirectoryBeside(const QString& programDirectory);
// A lesson is read-only: `path` is a scene in the lessons folder.
bool isLesson(const QString& path);
// Where Save As proposes to write the scene read from `path`: `path` itself,
// but for a lesson the user's documents folder (home when there is none),
// under the lesson's name.
QString saveAsProposal(const QString& path);

// The scenes of `directory` that load, in teaching order (the classic
// cascade first, then the variations, then whatever else is there).
std::vector<Lesson> findLessons(const QString& directory);

// The Lessons menu: one entry per lesson, its description as the tooltip.
class LessonsMenu : public QMenu {
    Q_OBJECT
public:
    explicit LessonsMenu(const std::vector<Lesson>& lessons, QWidget* parent = nullptr);

signals:
    void openRequested(const QString& path);
};

// Beside the view: what the open scene is about, in the author's words.
class LessonPanel : public QWidget {
    Q_OBJECT
public:
    explicit LessonPanel(QWidget* parent = nullptr);
    // `edited`: the scene was changed since its words were written, and the
    // panel says so above them, with a link to edit them.
    void showScene(const jl::Scene& scene, bool edited = false);
    void setLarge(bool large);
    QString text() const;

signals:
    void editTextRequested();  // the link under an edited scene's note

private:
    QTextBrowser* text_;
};

}  // namespace jl::ui
