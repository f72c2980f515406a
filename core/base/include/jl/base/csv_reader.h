// Reading back a CSV table as the writer writes it (jl/base/csv_writer.h,
// RFC 4180): fields split at commas, a quoted field may hold commas, line
// breaks and doubled double quotes. For joining tables the programs wrote,
// such as the shares of a design map.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jl {

using CsvRow = std::vector<std::string>;

// Every row of `text` (lines end in "\n" or "\r\n"; the last may lack its
// end), or nullopt and `error` set (a quote left open, text after a
// closing quote).
std::optional<std::vector<CsvRow>> readCsv(std::string_view text, std::string& error);

}  // namespace jl
