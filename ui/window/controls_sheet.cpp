#include "ui/window/controls_sheet.h"

#include <QAction>
#include <QMessageBox>

#include <algorithm>
#include <utility>
#include <vector>

namespace jl::ui {

namespace {

// The sheet is read by someone who wants to do something: its sections are
// the tasks, in the order a first session meets them.
enum Task { Watching, Scrubbing, Editing, Files, Presentation, Other, TaskCount };

QString taskTitle(int t) {
    static const char* titles[] = {QT_TR_NOOP("Watching"), QT_TR_NOOP("Scrubbing"),    QT_TR_NOOP("Editing"),
                                   QT_TR_NOOP("Files"),    QT_TR_NOOP("Presentation"), QT_TR_NOOP("Help")};
    return QObject::tr(titles[t]);
}

// An action's task, by its text without the '&' and the "...".
Task taskOf(const QString& what) {
    static const std::vector<std::pair<Task, QStringList>> tasks = {
        {Watching,
         {"Play", "Reset view", "Frame the ladder", "Frame the moving blocks", "Walk mode", "Follow the ladder",
          "Block numbers", "Corner numbers (0-3)", "Lengthwise orientation arrows"}},
        {Scrubbing, {"Step forward", "Step back", "Restart", "Run to the next event", "Loop a stretch"}},
        {Editing, {"Undo", "Redo", "Title and Description"}},
        {Files, {"New", "Open", "Save", "Save As", "Revert", "Quit"}},
        {Presentation, {"Presentation mode"}},
    };
    QString bare = what;
    bare.remove('&');
    if (bare.endsWith("...")) bare.chop(3);
    for (const auto& [task, texts] : tasks)
        if (texts.contains(bare)) return task;
    return Other;
}

using Rows = std::vector<std::pair<QString, QString>>;

// What the mouse does, by task; the keys come from the actions.
void addMouse(std::vector<Rows>& rows) {
    auto row = [&rows](Task t, const QString& what, const QString& does) { rows[t].emplace_back(what, does); };
    row(Watching, QObject::tr("Left-drag off the blocks, or right-drag"), QObject::tr("orbit the camera"));
    row(Watching, QObject::tr("Middle-drag"), QObject::tr("pan"));
    row(Watching, QObject::tr("Wheel"), QObject::tr("zoom toward the pointer"));
    row(Watching, QObject::tr("Walk mode"), QObject::tr("W A S D to move, Q E down and up, drag to look, Esc to stop"));
    row(Scrubbing, QObject::tr("Timeline, plots"), QObject::tr("click or drag to see that moment"));
    row(Scrubbing, QObject::tr("An event's mark on the timeline, an entry in Events"),
        QObject::tr("click to see that event's instant"));
    row(Editing, QObject::tr("Left-drag a block"),
        QObject::tr("push it with a spring (a held block: move the hand); recorded, so a replay repeats it"));
    row(Editing, QObject::tr("Shift + left-drag a block"),
        QObject::tr("the hand turns it about its centre: sweep round it; the angle snaps to quarter turns, the turn "
                    "takes as long as you did; a script row, undoable"));
    row(Editing, QObject::tr("Click by a hinge, then Delete (or right-click it: Cut hinge N)"),
        QObject::tr("cut the hinge at the moment shown (3-D view or side view); a script row, undoable"));
    row(Editing, QObject::tr("Left-drag a free corner onto another block's"),
        QObject::tr("join them where it snaps: a cut hinge's corners make the hinge again, other corners a pin"));
    row(Editing, QObject::tr("Right-click a block"),
        QObject::tr("Hold block N here, or Release block N: the hand takes it or lets go at the moment shown"));
    row(Editing, QObject::tr("Ladder, Simulation and Script panels"),
        QObject::tr("change the scene; every change can be undone"));
    row(Presentation, QObject::tr("Esc"), QObject::tr("leave presentation mode"));
}

}  // namespace

// The mouse and the keys in one page, by task. The keys are read from the
// actions themselves, so the page cannot drift from what the program does.
void showControlsSheet(QWidget* window) {
    std::vector<Rows> rows(TaskCount);
    addMouse(rows);
    Rows keys;
    for (QAction* a : window->findChildren<QAction*>()) {
        if (a->shortcut().isEmpty() || a->text().isEmpty()) continue;
        keys.emplace_back(a->shortcut().toString(QKeySequence::NativeText), a->text().remove('&'));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (const auto& key : keys) rows[taskOf(key.second)].push_back(key);
    QString text;
    for (int t = 0; t < TaskCount; ++t) {
        if (rows[t].empty()) continue;
        text += QString("<h3>%1</h3><table cellspacing=4>").arg(taskTitle(t));
        for (const auto& [what, does] : rows[t])
            text += QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(what.toHtmlEscaped(), does.toHtmlEscaped());
        text += "</table>";
    }
    auto* box = window->findChild<QMessageBox*>("controlsHelp");
    if (!box) {
        box = new QMessageBox(QMessageBox::Information, QObject::tr("Controls"), {}, QMessageBox::Close, window);
        box->setObjectName("controlsHelp");
        box->setModal(false);
        box->setTextFormat(Qt::RichText);
    }
    box->setText(text);
    box->show();
}

}  // namespace jl::ui
