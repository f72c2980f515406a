// Only a rename replaces a file in one piece, and only within one file
// system, so the temporary lives in the directory of the file it replaces.
#include "jl/base/output_file.h"

#include "jl/base/output_name.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <optional>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace jl {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kBufferBytes = 1u << 20;

bool writeAll(int fd, std::string_view text) {
    while (!text.empty()) {
        const ssize_t n = ::write(fd, text.data(), text.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;
            return false;
        }
        text.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

std::string directoryOf(const std::string& path) {
    const fs::path p(path);
    return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

// The directory entry of the rename must reach the disk too, or a crash
// could bring back the old file after success was reported.
void syncDirectory(const std::string& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

// Renames `from` to `to` unless `to` exists: a result kept aside must not
// take the place of a file the run did not make (the scene, another output).
bool renameNew(const std::string& from, const std::string& to) {
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0) return true;
    if (errno != EINVAL && errno != ENOSYS) return false;
    // A file system without RENAME_NOREPLACE: a link is never made over a file either.
    if (::link(from.c_str(), to.c_str()) != 0) return false;
    ::unlink(from.c_str());
    return true;
}

}  // namespace

bool writtenDirectly(const std::string& path) {
    const OutputName name = resolveOutputName(path);
    struct stat st {};
    return !name.error &&
           (name.descriptor || (::stat(name.path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)));
}

OutputFile::OutputFile(OutputFile&& other) noexcept { *this = std::move(other); }

OutputFile& OutputFile::operator=(OutputFile&& other) noexcept {
    if (this == &other) return *this;
    discard();
    path_ = std::move(other.path_);
    target_ = std::move(other.target_);
    temporary_ = std::exchange(other.temporary_, {});
    kept_ = std::move(other.kept_);
    buffer_ = std::move(other.buffer_);
    written_ = other.written_;
    error_ = std::move(other.error_);
    fd_ = std::exchange(other.fd_, -1);
    direct_ = other.direct_;
    return *this;
}

OutputFile::~OutputFile() { discard(); }

bool OutputFile::fail(const std::string& what, int error) {
    if (error_.empty()) error_ = what + ": " + std::strerror(error);
    return false;
}

bool OutputFile::open(const std::string& path) {
    discard();
    path_ = target_ = path;
    error_.clear();
    buffer_.clear();
    kept_.clear();
    written_ = 0;
    direct_ = false;
    if (path.empty()) {  // a temporary would be made in the current directory, and no rename could place it
        error_ = "no file name given";
        return false;
    }
    const OutputName name = resolveOutputName(path);
    if (name.error) return fail("cannot tell which file this name stands for", name.error);
    if (name.descriptor) {
        direct_ = true;
        fd_ = ::fcntl(*name.descriptor, F_DUPFD_CLOEXEC, 3);
        return fd_ >= 0 || fail("cannot write to it", errno);
    }
    // Replacing a symbolic link would turn it into a file: replace what it
    // points to, the very file the clash checks compared (jl/base/output_name.h).
    target_ = name.path;
    struct stat st {};
    const bool exists = ::stat(target_.c_str(), &st) == 0;
    if (exists && S_ISDIR(st.st_mode)) return fail("cannot write the file", EISDIR);
    if (exists && !S_ISREG(st.st_mode)) {
        direct_ = true;
        fd_ = ::open(target_.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
        return fd_ >= 0 || fail("cannot open it", errno);
    }
    const std::string dir = directoryOf(target_);
    std::string temporary = (fs::path(dir) / (fs::path(target_).filename().string() + ".partial-XXXXXX")).string();
    fd_ = ::mkostemp(temporary.data(), O_CLOEXEC);
    if (fd_ < 0) return fail("cannot create a temporary file in " + dir, errno);
    temporary_ = std::move(temporary);
    // Keep the permissions of the file being replaced; new files get 0644.
    ::fchmod(fd_, exists ? (st.st_mode & 07777) : 0644);
    return true;
}

bool OutputFile::write(std::string_view text) {
    if (failed()) return false;
    if (fd_ < 0) return fail("cannot write the file", EBADF);
    buffer_.append(text);
    return buffer_.size() < kBufferBytes || flush();
}

bool OutputFile::flush() {
    if (failed()) return false;
    if (fd_ < 0) return fail("cannot write the file", EBADF);
    const bool written = writeAll(fd_, buffer_);
    if (written) {
        written_ += buffer_.size();
    } else if (!direct_) {
        // What was flushed before is whole (rows, events): a piece the disk
        // took only part of is taken back, so a kept result does not end torn.
        // Should the truncation fail too, the error said is still the write's.
        const int error = errno;
        [[maybe_unused]] const int truncated = ::ftruncate(fd_, static_cast<off_t>(written_));
        errno = error;
    }
    buffer_.clear();
    return written || fail("cannot write the file", errno);
}

bool OutputFile::close() {
    if (fd_ < 0) return true;
    const int closed = ::close(std::exchange(fd_, -1));
    // Linux releases the descriptor even when close is interrupted.
    return closed == 0 || errno == EINTR || fail("cannot write the file", errno);
}

bool OutputFile::commit() {
    bool ok = flush();
    if (ok && !direct_ && ::fsync(fd_) != 0) ok = fail("cannot write the file", errno);
    ok = close() && ok;
    if (direct_ || !ok) {
        if (!ok) discard();
        return ok;
    }
    if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
        fail("cannot replace the file", errno);
        discard();
        return false;
    }
    temporary_.clear();
    syncDirectory(directoryOf(target_));
    return true;
}

bool OutputFile::keepAs(const std::string& other) {
    flush();  // a failed write still leaves what came before it
    const bool closed = close();
    if (direct_ || temporary_.empty()) return closed;
    // Whatever happens, the temporary is not removed: it holds the result,
    // under `other` when that names no file yet, else under its own name.
    kept_ = std::exchange(temporary_, {});
    if (renameNew(kept_, other)) kept_ = other;
    return closed;
}

void OutputFile::discard() {
    if (fd_ >= 0) ::close(std::exchange(fd_, -1));
    if (!temporary_.empty()) ::unlink(std::exchange(temporary_, {}).c_str());
    buffer_.clear();
}

std::string writeWholeFile(const std::string& path, std::string_view text) {
    OutputFile file;
    if (file.open(path) && file.write(text) && file.commit()) return {};
    return file.error().empty() ? std::string("cannot write the file") : file.error();
}

}  // namespace jl
