#include "jl/scene/yaml_comments.h"

namespace jl {

bool hasComments(std::string_view text) {
    char quote = 0;  // the quote a quoted scalar opened, or 0
    char previous = '\n';
    for (const char c : text) {
        if (quote) {
            if (c == quote) quote = 0;  // '' inside single quotes reopens at once: harmless here
        } else if (c == '#' && (previous == '\n' || previous == ' ' || previous == '\t')) {
            return true;
        } else if ((c == '"' || c == '\'') && (previous == ' ' || previous == '\n' || previous == '[' ||
                                               previous == '{' || previous == ',' || previous == ':')) {
            quote = c;
        }
        if (c == '\n' && quote == '\'') quote = 0;  // our files never fold a quoted scalar over lines
        if (c == '\n' && quote == '"') quote = 0;
        previous = c;
    }
    return false;
}

}  // namespace jl
