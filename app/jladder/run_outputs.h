// The files a headless run writes (block poses, energies, events), written
// as the run goes, each through a temporary (jl/base/output_file.h): a run that
// completes replaces the files; one that fails or is interrupted leaves them
// as they were and keeps what it computed beside them in FILE.partial; one
// that is killed leaves it in FILE.partial-XXXXXX.
#pragma once

#include "jl/base/output_file.h"
#include "jl/sim/recording.h"

#include <sstream>
#include <string>
#include <vector>

namespace jl::cli {

class RunOutputs : public RecordTarget {
public:
    enum class Table { Poses, Energy, Events };

    // `option` names the output in messages ("--frames").
    void add(Table table, const std::string& option, const std::string& path);
    // Why the outputs cannot be written as asked: one of them is `input`, or
    // two are one file (through links too), or "" when they can.
    std::string clash(const std::string& input) const;
    // Creates every file (its temporary) and writes the headers.
    bool open();
    bool wantsFrames() const;
    // How many frames the run will write: the first frame's bytes times
    // these, when over 1 GiB, are said on stderr, after `command`, before
    // the run goes on (a small --every over a long run fills a disk).
    void expectFrames(double count, const char* command);

    bool frame(const Frame& f) override;
    bool event(const Event& e) override;

    // `complete`: every file is replaced; else each is left as it was and
    // what the run computed goes beside it. Says on stderr, after `command`,
    // where that is and what could not be written.
    bool finish(bool complete, const char* command);
    // "PATH: what failed", the first failure.
    const std::string& error() const { return error_; }

private:
    struct Output {
        Table table;
        std::string option, path;
        OutputFile file;
        bool first = true;  // Events: no comma before the first
    };
    bool put(Output& o, const std::string& text);

    std::vector<Output> outputs_;
    std::ostringstream text_;  // reused for every frame's rows
    std::string error_;
    double expectedFrames_ = 0;  // 0: the first frame is written
    const char* command_ = "";
};

}  // namespace jl::cli
