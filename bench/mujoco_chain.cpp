#ifdef JL_BENCH_PEERS

#include "bench/mujoco_chain.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace jl::bench {

mjModel* loadNestedChain(const std::string& head, const std::vector<std::string>& bodies) {
    // The XML parser allows ~100 nested elements, so the chain is split into
    // files of 40 bodies, each included inside the last body of the one before.
    constexpr int perFile = 40;
    const int n = int(bodies.size());
    std::vector<std::string> files;
    for (int first = 0; first < n; first += perFile) {
        const int last = std::min(n, first + perFile);
        std::string x = first == 0 ? "<mujoco>" + head + "<worldbody>" : "<mujoco>";
        for (int i = first; i < last; ++i) x += bodies[size_t(i)];
        if (last < n) x += "<include file='chain" + std::to_string(last / perFile) + ".xml'/>";
        for (int i = first; i < last; ++i) x += "</body>";
        x += first == 0 ? "</worldbody></mujoco>" : "</mujoco>";
        files.push_back(x);
    }
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    for (size_t k = 0; k < files.size(); ++k) {
        const std::string name = "chain" + std::to_string(k) + ".xml";
        mj_makeEmptyFileVFS(&vfs, name.c_str(), int(files[k].size()));
        std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, name.c_str())], files[k].data(), files[k].size());
    }
    char error[512] = "";
    mjModel* m = mj_loadXML("chain0.xml", &vfs, error, sizeof error);
    mj_deleteVFS(&vfs);
    if (!m) std::fprintf(stderr, "mujoco: %s\n", error);
    return m;
}

}  // namespace jl::bench

#endif
