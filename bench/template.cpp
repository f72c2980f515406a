#include "bench/template.h"

#include "bench/report_templates.h"

#include <set>

namespace jl::bench {

std::optional<std::string> fillTemplate(std::string_view text, const TemplateValues& values, std::string& error) {
    std::string out;
    std::set<std::string> used;
    size_t at = 0;
    while (true) {
        const size_t open = text.find("{{", at);
        if (open == std::string_view::npos) break;
        const size_t close = text.find("}}", open + 2);
        if (close == std::string_view::npos) {
            error = "a placeholder is not closed: " + std::string(text.substr(open, 40));
            return std::nullopt;
        }
        const std::string name(text.substr(open + 2, close - open - 2));
        const auto it = values.find(name);
        if (it == values.end()) {
            error = "no value for {{" + name + "}}";
            return std::nullopt;
        }
        out.append(text.substr(at, open - at));
        out += it->second;
        used.insert(name);
        at = close + 2;
    }
    out.append(text.substr(at));
    for (const auto& [name, value] : values)
        if (!used.count(name)) {
            error = "the template has no place for {{" + name + "}}";
            return std::nullopt;
        }
    return out;
}

std::string_view reportTemplate(std::string_view name) {
    for (const auto& [key, text] : kReportTemplates)
        if (key == name) return text;
    return {};
}

}  // namespace jl::bench
