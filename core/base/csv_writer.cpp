#include "jl/base/csv_writer.h"

#include <charconv>
#include <cmath>

namespace jl {

std::string csvField(std::string_view text) {
    if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';  // a quote inside is doubled
        out += c;
    }
    return out + '"';
}

void CsvWriter::separate() {
    if (!first_) out_ << ',';
    first_ = false;
}

void CsvWriter::cell(std::string_view text) {
    separate();
    out_ << csvField(text);
}

void CsvWriter::cell(double x) {
    separate();
    if (!std::isfinite(x)) return;
    char text[32];
    const auto written = digits_ > 0 ? std::to_chars(text, text + sizeof text, x, std::chars_format::general, digits_)
                                     : std::to_chars(text, text + sizeof text, x);
    out_.write(text, written.ptr - text);
}

void CsvWriter::end() {
    out_ << '\n';
    first_ = true;
}

}  // namespace jl
