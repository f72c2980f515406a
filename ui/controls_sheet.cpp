#include "ui/controls_sheet.h"

#include <QAction>
#include <QMessageBox>

#include <algorithm>
#include <utility>
#include <vector>

namespace jl::ui {

// The mouse and the keys in one page. The keys are read from the actions
// themselves, so the page cannot drift from what the program does.
void showControlsSheet(QWidget* window) {
    QString keys;
    std::vector<std::pair<QString, QString>> rows;
    for (QAction* a : window->findChildren<QAction*>()) {
        if (a->shortcut().isEmpty() || a->text().isEmpty()) continue;
        rows.emplace_back(a->text().remove('&'), a->shortcut().toString(QKeySequence::NativeText));
    }
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    for (const auto& [what, key] : rows)
        keys += QString("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(key.toHtmlEscaped(), what.toHtmlEscaped());
    const QString mouse = QObject::tr(
        "<tr><td><b>Left-drag a block</b></td><td>push it with a spring (a held block: move the hand); recorded, so "
        "a replay repeats it</td></tr>"
        "<tr><td><b>Shift + left-drag a block</b></td><td>the hand turns it about its centre: sweep round it; the "
        "angle snaps to quarter turns, the turn takes as long as you did; a script row, undoable</td></tr>"
        "<tr><td><b>Left-drag off the blocks, or right-drag</b></td><td>orbit the camera about the ladder</td></tr>"
        "<tr><td><b>Middle-drag</b></td><td>pan</td></tr>"
        "<tr><td><b>Wheel</b></td><td>zoom toward the pointer</td></tr>"
        "<tr><td><b>Walk mode</b></td><td>W A S D to move, Q E down and up, drag to look, Esc to stop</td></tr>"
        "<tr><td><b>Timeline, plots</b></td><td>click or drag to see that moment</td></tr>"
        "<tr><td><b>An event's mark on the timeline, an entry in Events</b></td><td>click to see that event's "
        "instant</td></tr>");
    auto* box = window->findChild<QMessageBox*>("controlsHelp");
    if (!box) {
        box = new QMessageBox(QMessageBox::Information, QObject::tr("Controls"), {}, QMessageBox::Close, window);
        box->setObjectName("controlsHelp");
        box->setModal(false);
        box->setTextFormat(Qt::RichText);
    }
    box->setText(
        QObject::tr("<h3>Mouse</h3><table cellspacing=4>%1</table><h3>Keys</h3><table cellspacing=4>%2</table>")
            .arg(mouse, keys));
    box->show();
}

}  // namespace jl::ui
