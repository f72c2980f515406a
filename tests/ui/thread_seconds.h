// CPU seconds of every thread of this process, by name (/proc/self/task):
// llvmpipe's threads (the software renderer's) summed as "llvmpipe", the
// thread that runs main() (the UI thread) as "ui". For measurements printed
// by the timing tests and tools/view_draw_cost. threadWaits(): the seconds
// each has waited on a run queue for a processor (schedstat), by the same
// names: what a thread that falls behind lost to the other threads.
#pragma once

#include <QDir>
#include <QString>
#include <QStringList>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>

namespace jl::test {

// A thread's name as the measurements print it.
inline std::string threadName(const QString& tid) {
    std::ifstream in(("/proc/self/task/" + tid + "/comm").toStdString());
    std::string name;
    std::getline(in, name);
    if (name.rfind("llvmpipe", 0) == 0) name = "llvmpipe";
    if (tid == QString::number(getpid())) name = "ui";
    return name;
}

inline QStringList threadIds() { return QDir("/proc/self/task").entryList(QDir::Dirs | QDir::NoDotAndDotDot); }

inline std::map<std::string, double> threadWaits() {
    std::map<std::string, double> out;
    for (const QString& tid : threadIds()) {
        std::ifstream in(("/proc/self/task/" + tid + "/schedstat").toStdString());
        long long ran = 0, waited = 0;
        if (in >> ran >> waited) out[threadName(tid)] += double(waited) / 1e9;
    }
    return out;
}

inline std::map<std::string, double> threadSeconds() {
    std::map<std::string, double> out;
    const double tick = double(sysconf(_SC_CLK_TCK));
    for (const QString& tid : threadIds()) {
        std::ifstream in(("/proc/self/task/" + tid + "/stat").toStdString());
        std::string line;
        std::getline(in, line);
        const auto open = line.find('('), close = line.rfind(')');
        if (open == std::string::npos || close == std::string::npos) continue;
        // Fields after the name: state is field 3, utime 14 and stime 15.
        std::istringstream rest(line.substr(close + 2));
        std::string field;
        double utime = 0, stime = 0;
        for (int i = 3; i <= 15 && rest >> field; ++i) {
            if (i == 14) utime = std::stod(field);
            if (i == 15) stime = std::stod(field);
        }
        out[threadName(tid)] += (utime + stime) / tick;
    }
    return out;
}

}  // namespace jl::test
