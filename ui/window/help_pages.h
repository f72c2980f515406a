// Help > First steps and Help > Concepts: pages compiled into the program
// from docs/help, so the documentation and the Help menu are one copy.
#pragma once

#include <QString>

class QLabel;
class QMenu;
class QWidget;

namespace jl::ui {

// Shows (or brings back) the page docs/help/<page>.html in a window that
// does not block `window`, scrolled to `anchor` when one is given.
void showHelpPage(QWidget* window, const QString& page, const QString& anchor = {});

// Ties a status-bar label to the Concepts page's section `anchor`: its
// tooltip says so, and a click on it opens the page there. The anchor is
// kept in the label's "concept" property, so the tie can be checked.
void linkToConcept(QLabel* label, const QString& anchor);

// Adds First steps and Concepts to the Help menu `help` of `window`.
void addHelpPages(QMenu* help, QWidget* window);

// Ties the status bar's terms of `window` (the labels named rate, energy,
// residual and warning) to their sections of the Concepts page.
void linkStatusBarToConcepts(QWidget* window);

}  // namespace jl::ui
