// CPU seconds of every thread of this process, by name (/proc/self/task):
// llvmpipe's threads (the software renderer's) summed as "llvmpipe", the
// thread that runs main() (the UI thread) as "ui". For measurements printed
// by the timing tests and tools/view_draw_cost.
#pragma once

#include <QDir>
#include <QString>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>

namespace jl::test {

inline std::map<std::string, double> threadSeconds() {
    std::map<std::string, double> out;
    const double tick = double(sysconf(_SC_CLK_TCK));
    const QString self = QString::number(getpid());
    for (const QString& tid : QDir("/proc/self/task").entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        std::ifstream in(("/proc/self/task/" + tid + "/stat").toStdString());
        std::string line;
        std::getline(in, line);
        const auto open = line.find('('), close = line.rfind(')');
        if (open == std::string::npos || close == std::string::npos) continue;
        std::string name = line.substr(open + 1, close - open - 1);
        // Fields after the name: state is field 3, utime 14 and stime 15.
        std::istringstream rest(line.substr(close + 2));
        std::string field;
        double utime = 0, stime = 0;
        for (int i = 3; i <= 15 && rest >> field; ++i) {
            if (i == 14) utime = std::stod(field);
            if (i == 15) stime = std::stod(field);
        }
        if (name.rfind("llvmpipe", 0) == 0) name = "llvmpipe";
        if (tid == self) name = "ui";
        out[name] += (utime + stime) / tick;
    }
    return out;
}

}  // namespace jl::test
