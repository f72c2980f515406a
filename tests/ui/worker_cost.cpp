// Not a test: a harness for counting what the window's simulation thread
// does beside the engine (docs/desktop-performance.md). It plays (at 4x,
// so flat out) or seeks the classic design with N blocks up to simulated
// time T through SimWorker, as the window does, taking the frames as the
// window's controller does, with no window. Under callgrind its counts
// compare with `jladder run` over the same span:
//   valgrind --tool=callgrind build/bin/worker_cost play 10000 1.2
// With a SPEED of 1 it plays paced, as a user watches it, and says the
// real-time factor it kept.
#include "jl/scene/scene_io.h"
#include "ui/play/sim_worker.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

using namespace jl::ui;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: worker_cost play|seek BLOCKS UNTIL [SPEED]\n");
        return 2;
    }
    const bool play = std::strcmp(argv[1], "play") == 0;
    const int blocks = std::atoi(argv[2]);
    const double until = std::atof(argv[3]);
    const double speed = argc > 4 ? std::atof(argv[4]) : 4.0;
    auto load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
    load.scene->ladder->blocks = blocks;
    load.scene->duration = until;  // playing stops there
    SimWorker w(std::size_t(512) << 20);
    std::thread t([&] { w.run(); });
    w.post(cmd::Load{*load.scene});
    if (play) {
        w.post(cmd::Speed{speed});
        w.post(cmd::Play{});
    } else {
        w.post(cmd::Seek{until});
    }
    const auto started = std::chrono::steady_clock::now();
    std::uint64_t lastSerial = 0;
    std::shared_ptr<const SimStatus> s;
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(16));
        s = w.status();
        if (s->serial == lastSerial) continue;
        lastSerial = s->serial;
        if (s->newFrames) w.taken(s->firstNewFrame + s->newFrames->size());
        if (!s->playing && s->frame && s->frame->time >= until - 1e-9) break;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    w.post(cmd::Pause{});
    w.post(cmd::Quit{});
    t.join();
    std::printf("%.3f s wall (%.3fx); ", wall, until / wall);
    std::printf("head %.4f frames %d events %zu hash %016llx serial %llu\n", s->headTime, s->frameCount,
                s->events ? s->events->size() : 0, (unsigned long long)s->headHash, (unsigned long long)s->serial);
}
