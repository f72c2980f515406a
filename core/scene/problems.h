// Collects the diagnostics of one file, up to a cap, and hands them back in file order.
#pragma once

#include "jl/base/diagnostic.h"

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace jl {

class Problems {
public:
    Problems(std::string file, std::size_t maxErrors) : file_(std::move(file)), max_(maxErrors) {}

    // line and column are 1-based; 0 means the whole file.
    void add(int line, int column, std::string message) {
        if (list_.size() < max_) {
            list_.push_back({file_, line, column, std::move(message)});
        } else if (!truncated_) {
            truncated_ = true;
            list_.push_back({file_, line, column, "too many problems; the rest are not listed"});
        }
    }
    bool empty() const { return list_.empty(); }
    std::size_t size() const { return list_.size(); }
    const std::string& file() const { return file_; }

    // Sorted by position so the list reads top to bottom like the file.
    std::vector<Diagnostic> take() {
        std::stable_sort(list_.begin(), list_.end(), [](const Diagnostic& a, const Diagnostic& b) {
            return std::pair(a.line, a.column) < std::pair(b.line, b.column);
        });
        return std::move(list_);
    }

private:
    std::string file_;
    std::size_t max_;
    bool truncated_ = false;
    std::vector<Diagnostic> list_;
};

}  // namespace jl
