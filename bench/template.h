// The report's prose lives in Markdown templates (bench/report/*.md), built
// into the program; the benchmark only fills in what it measured. {{name}}
// is replaced by the value of that name. Every placeholder needs a value and
// every value a placeholder, so prose and numbers cannot drift apart.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace jl::bench {

using TemplateValues = std::map<std::string, std::string>;

// The filled text, or nullopt with `error` saying which name is missing or unused.
std::optional<std::string> fillTemplate(std::string_view text, const TemplateValues& values, std::string& error);

// The template bench/report/NAME.md as built in (empty if there is none).
std::string_view reportTemplate(std::string_view name);

}  // namespace jl::bench
