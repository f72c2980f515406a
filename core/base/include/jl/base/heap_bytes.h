// What an object holds on the heap: the memory a copy of it takes, for the
// budgets that keep copies (the timeline's keyframes). Counted as glibc's
// malloc hands blocks out: the request and its 8-byte header, in steps of
// 16 bytes, at least 32 (a list of one int costs 32 bytes, not 4).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace jl {

inline std::size_t heapBlock(std::size_t bytes) {
    return bytes == 0 ? 0 : std::max<std::size_t>(32, (bytes + 8 + 15) / 16 * 16);
}

template <class T>
std::size_t heapBytes(const std::vector<T>& v) {
    return heapBlock(v.capacity() * sizeof(T));
}

inline std::size_t heapBytes(const Eigen::VectorXd& v) { return heapBlock(std::size_t(v.size()) * sizeof(double)); }

// A list of lists: the outer block and each inner one.
template <class T>
std::size_t heapBytes(const std::vector<std::vector<T>>& v) {
    std::size_t n = heapBlock(v.capacity() * sizeof(std::vector<T>));
    for (const std::vector<T>& x : v) n += heapBytes(x);
    return n;
}

}  // namespace jl
