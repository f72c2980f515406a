// Links are followed by hand, one at a time, so that the count is ours and
// not the kernel's alone: std::filesystem gives up at ELOOP and reports "no
// such file", while a hand-made loop without a limit would follow a chain
// the kernel refuses. 40 is the kernel's own limit (MAXSYMLINKS).
#include "jl/base/output_name.h"

#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <sys/stat.h>
#include <unistd.h>

namespace jl {

namespace {

namespace fs = std::filesystem;

constexpr int kMaxLinks = 40;

std::optional<int> descriptorOf(std::string_view path) {
    if (path == "/dev/stdout") return 1;
    if (path == "/dev/stderr") return 2;
    for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
        if (!path.starts_with(prefix)) continue;
        const std::string_view digits = path.substr(prefix.size());
        int fd = -1;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), fd);
        if (error == std::errc{} && end == digits.data() + digits.size() && fd >= 0) return fd;
    }
    return std::nullopt;
}

std::optional<std::string> readLink(const std::string& path) {
    std::string to(PATH_MAX, '\0');
    const ssize_t n = ::readlink(path.c_str(), to.data(), to.size());
    if (n < 0 || static_cast<std::size_t>(n) >= to.size()) return std::nullopt;
    to.resize(static_cast<std::size_t>(n));
    return to;
}

// Whether the names stand for files that exist, and which.
bool identify(const OutputName& name, struct stat& st) {
    if (name.descriptor) return ::fstat(*name.descriptor, &st) == 0;
    return ::stat(name.path.c_str(), &st) == 0;
}

}  // namespace

OutputName resolveOutputName(const std::string& path) {
    std::string p = path;
    for (int links = 0;; ++links) {
        if (const auto fd = descriptorOf(p)) return {p, fd, 0};
        struct stat st {};
        if (::lstat(p.c_str(), &st) != 0) {
            if (errno == ENOENT) break;  // a file not made yet
            return {p, std::nullopt, errno};
        }
        if (!S_ISLNK(st.st_mode)) break;
        if (links == kMaxLinks) return {p, std::nullopt, ELOOP};
        const auto to = readLink(p);
        if (!to) return {p, std::nullopt, errno ? errno : ENAMETOOLONG};
        const fs::path link(p);
        p = fs::path(*to).is_absolute() ? *to : (link.parent_path() / *to).string();
    }
    // The directory without links, so that two names of one file not made
    // yet compare equal. A directory that does not exist is left to the
    // writer, whose temporary cannot be made there and says so.
    const fs::path name(p);
    const std::string file = name.filename().string();
    if (file.empty() || file == "." || file == "..") return {p, std::nullopt, 0};
    const std::string dir = name.has_parent_path() ? name.parent_path().string() : std::string(".");
    char* real = ::realpath(dir.c_str(), nullptr);
    if (!real) {
        if (errno == ENOENT) return {p, std::nullopt, 0};
        return {p, std::nullopt, errno};
    }
    std::string resolved = (fs::path(real) / file).string();
    std::free(real);
    return {resolved, std::nullopt, 0};
}

bool sameOutput(const OutputName& a, const OutputName& b) {
    if (a.error || b.error) return false;
    struct stat sa {
    }, sb{};
    const bool aExists = identify(a, sa), bExists = identify(b, sb);
    if (aExists && bExists) return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    return !aExists && !bExists && a.path == b.path;
}

}  // namespace jl
