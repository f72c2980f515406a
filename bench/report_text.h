// The words and numbers every section of the benchmark's report is written
// with: numbers to a few digits, the machine, templates filled, a section
// saved alone (jladder bench --only NAME).
#pragma once

#include "bench/template.h"

#include <filesystem>
#include <string>

namespace jl::bench {

std::string num(double x);              // 3 significant digits, "failed" if not finite
std::string sig(double x, int digits);  // `digits` significant digits, "—" if not finite
std::string cpuTime(double seconds);    // in us below 1 ms, else in ms, 3 digits
std::string cpuModel();                 // from /proc/cpuinfo
// The template `name` filled with `values`; on a mismatch, says so in the
// report itself and on stderr, and clears `ok`.
std::string filled(const char* name, const TemplateValues& values, bool& ok);
// One section alone, as `jladder bench --only NAME` writes it.
bool writeSection(const char* name, bool quick, const std::filesystem::path& report, const std::string& section,
                  bool ok);

}  // namespace jl::bench
