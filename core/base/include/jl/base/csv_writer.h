// The one CSV writer of every table the programs write (runs, exports, the
// design map, the benchmark), quoting by RFC 4180 so that any reader splits
// rows as they were written: a field holding a comma, a double quote or a
// line break is put in double quotes, with its double quotes doubled. A
// number that is not finite is an empty field: a bare "nan" or "inf" is text
// where a reader expects a number, and not every reader takes it.
#pragma once

#include <concepts>
#include <ostream>
#include <string>
#include <string_view>

namespace jl {

// A field as RFC 4180 writes it: quoted only when it must be.
std::string csvField(std::string_view text);

class CsvWriter {
public:
    // Numbers are written as the shortest text that reads back to the same
    // double (std::to_chars), so that a table read back is the run itself;
    // `digits` > 0 rounds them instead to that many significant digits, for
    // tables of measurements read by eye (the benchmark's).
    explicit CsvWriter(std::ostream& out, int digits = 0) : out_(out), digits_(digits) {}

    // One row: every cell, then the line's end ("\n").
    template <class... Cells>
    void row(const Cells&... cells) {
        (cell(cells), ...);
        end();
    }

    void cell(std::string_view text);
    void cell(const char* text) { cell(std::string_view(text)); }
    void cell(const std::string& text) { cell(std::string_view(text)); }
    void cell(double x);
    template <std::integral T>
    void cell(T n) {
        separate();
        if constexpr (std::same_as<T, bool>)
            out_ << (n ? 1 : 0);
        else
            out_ << n;
    }
    void end();

private:
    void separate();

    std::ostream& out_;
    int digits_;
    bool first_ = true;
};

}  // namespace jl
