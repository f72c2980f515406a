#include "app/jladder/run_outputs.h"

#include "app/jladder/options.h"
#include "jl/sim/event_json.h"
#include "jl/sim/frame_csv.h"

#include <cstdio>
#include <filesystem>

namespace jl::cli {

void RunOutputs::add(Table table, const std::string& option, const std::string& path) {
    outputs_.push_back({table, option, path, {}, true});
}

std::string RunOutputs::clash(const std::string& input) const {
    for (const Output& o : outputs_)
        if (std::string why = unresolvedOutput(o.option, o.path); !why.empty()) return why;
    for (std::size_t i = 0; i < outputs_.size(); ++i) {
        const Output& o = outputs_[i];
        if (sameFile(o.path, input))
            return o.option + " " + o.path + " is the scene file " + input + "; writing it would destroy the scene";
        // Two outputs written straight into one device or pipe lose nothing;
        // a rename of one over the other would.
        for (std::size_t k = 0; k < i; ++k)
            if (sameFile(o.path, outputs_[k].path) && !(writtenDirectly(o.path) && writtenDirectly(outputs_[k].path)))
                return outputs_[k].option + " and " + o.option + " name the same file (" + o.path +
                       "); one would overwrite the other, give each its own";
    }
    return {};
}

bool RunOutputs::open() {
    for (Output& o : outputs_) {
        if (!o.file.open(o.path)) {
            error_ = o.path + ": " + o.file.error();
            return false;
        }
        text_.str({});
        switch (o.table) {
            case Table::Poses:
                writePosesCsvHeader(text_);
                break;
            case Table::Energy:
                writeEnergyCsvHeader(text_);
                break;
            case Table::Events:
                writeEventsJsonStart(text_);
                break;
        }
        if (!put(o, text_.str())) return false;
    }
    return true;
}

bool RunOutputs::wantsFrames() const {
    for (const Output& o : outputs_)
        if (o.table != Table::Events) return true;
    return false;
}

// Every piece goes to the system at once: a killed run then leaves every
// frame it wrote in the temporary.
bool RunOutputs::put(Output& o, const std::string& text) {
    if (o.file.write(text) && o.file.flush()) return true;
    if (error_.empty()) error_ = o.path + ": " + o.file.error();
    return false;
}

void RunOutputs::expectFrames(double count, const char* command) {
    expectedFrames_ = count;
    command_ = command;
}

bool RunOutputs::frame(const Frame& f) {
    bool ok = true;
    double bytes = 0;
    for (Output& o : outputs_) {
        if (o.table == Table::Events) continue;
        text_.str({});
        if (o.table == Table::Poses)
            writePosesCsvRows(text_, f);
        else
            writeEnergyCsvRow(text_, f);
        bytes += double(text_.str().size());
        ok = put(o, text_.str()) && ok;
    }
    constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
    if (expectedFrames_ > 0 && bytes * expectedFrames_ > kGiB)
        std::fprintf(stderr,
                     "%s: this run will write about %.3g GiB of frames (%.0f frames of about %.0f bytes); a larger "
                     "--every or a shorter --until writes less\n",
                     command_, bytes * expectedFrames_ / kGiB, expectedFrames_, bytes);
    expectedFrames_ = 0;
    return ok;
}

bool RunOutputs::event(const Event& e) {
    bool ok = true;
    for (Output& o : outputs_) {
        if (o.table != Table::Events) continue;
        text_.str({});
        writeEventJson(text_, e, o.first);
        ok = put(o, text_.str()) && ok;
        o.first = false;
    }
    return ok;
}

bool RunOutputs::finish(bool complete, const char* command) {
    bool ok = true;
    // All the files or none: every one has all its bytes with the system
    // before the first is renamed into place, so that a failure in the last
    // (a full disk) does not leave the others replaced.
    for (Output& o : outputs_) {
        if (o.table == Table::Events && !o.file.failed()) {
            text_.str({});
            writeEventsJsonEnd(text_);
            put(o, text_.str());
        }
        if (complete && !o.file.flush()) {
            if (error_.empty()) error_ = o.path + ": " + o.file.error();
            ok = complete = false;
        }
    }
    for (Output& o : outputs_) {
        if (complete && o.file.commit()) continue;
        if (complete) {
            if (error_.empty()) error_ = o.path + ": " + o.file.error();
            ok = false;
            continue;
        }
        if (o.file.direct()) continue;
        const std::string partial = o.path + ".partial";
        std::error_code ec;
        const bool existed = std::filesystem::exists(o.path, ec);
        const bool closed = o.file.keepAs(partial);
        std::string aside;  // why the result is not in FILE.partial
        if (o.file.kept() != partial)
            aside = std::filesystem::symlink_status(partial, ec).type() != std::filesystem::file_type::not_found
                        ? " (" + partial + " is there already, and is left as it is)"
                        : " (" + partial + " could not be made)";
        std::fprintf(stderr, "%s: the run did not complete: %s is %s; what the run wrote of it is in %s%s\n", command,
                     o.path.c_str(), existed ? "left as it was" : "not made", o.file.kept().c_str(), aside.c_str());
        if (!closed) {
            if (error_.empty()) error_ = o.path + ": " + o.file.error();
            ok = false;
        }
    }
    if (!error_.empty()) std::fprintf(stderr, "%s: %s\n", command, error_.c_str());
    return ok && error_.empty();
}

}  // namespace jl::cli
