#include "jl/base/csv_reader.h"

namespace jl {

std::optional<std::vector<CsvRow>> readCsv(std::string_view text, std::string& error) {
    std::vector<CsvRow> rows;
    CsvRow row;
    std::string field;
    std::size_t i = 0, line = 1;
    const auto endField = [&] {
        row.push_back(std::move(field));
        field.clear();
    };
    while (i < text.size()) {
        if (text[i] == '"' && field.empty()) {
            // A quoted field: up to the quote that is not doubled.
            const std::size_t opened = line;
            for (++i;; ++i) {
                if (i >= text.size()) {
                    error = "line " + std::to_string(opened) + ": a quoted field is not closed";
                    return std::nullopt;
                }
                if (text[i] == '\n') ++line;
                if (text[i] != '"') {
                    field += text[i];
                } else if (i + 1 < text.size() && text[i + 1] == '"') {
                    field += '"';
                    ++i;
                } else {
                    ++i;
                    break;
                }
            }
            if (i < text.size() && text[i] != ',' && text[i] != '\n' && text.substr(i, 2) != "\r\n") {
                error = "line " + std::to_string(line) + ": text after a closing quote";
                return std::nullopt;
            }
            continue;
        }
        if (text[i] == ',') {
            endField();
        } else if (text[i] == '\n' || text.substr(i, 2) == "\r\n") {
            if (text[i] == '\r') ++i;
            endField();
            rows.push_back(std::move(row));
            row.clear();
            ++line;
        } else {
            field += text[i];
        }
        ++i;
    }
    if (!field.empty() || !row.empty()) {
        endField();
        rows.push_back(std::move(row));
    }
    return rows;
}

}  // namespace jl
