// sky_against.cpp — the sky solver of two (or more) revisions side by side
// in one process (scripts/sky_cost_against.sh builds it): each round times
// one solve of every library at every sun, interleaved, so that a busy or
// throttled machine slows them alike; the best of the rounds per sun and
// library, and its ratio to the first library's, are printed.
//
//   sky_against THREADS ROUNDS LIB SINGLE [LIB SINGLE ...]
//     THREADS: 0 = all hardware threads; SINGLE 1: single scattering only.
#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Create = void* (*)(int, int);
using SolveMs = double (*)(void*, double);
using Destroy = void (*)(void*);

struct Library {
    std::string name;
    void* solver = nullptr;
    SolveMs solve = nullptr;
    Destroy destroy = nullptr;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5 || (argc - 3) % 2 != 0) {
        std::fprintf(stderr, "usage: %s THREADS ROUNDS LIB SINGLE [LIB SINGLE ...]\n", argv[0]);
        return 2;
    }
    const int threads = std::atoi(argv[1]), rounds = std::max(std::atoi(argv[2]), 1);
    std::vector<Library> libs;
    for (int i = 3; i + 1 < argc; i += 2) {
        void* h = dlopen(argv[i], RTLD_NOW | RTLD_LOCAL);
        if (h == nullptr) {
            std::fprintf(stderr, "sky_against: %s\n", dlerror());
            return 1;
        }
        Library lib;
        const std::string path = argv[i];
        lib.name = path.substr(path.rfind('/') + 1) + (std::atoi(argv[i + 1]) != 0 ? " ss" : "");
        auto create = reinterpret_cast<Create>(dlsym(h, "aerialShimCreate"));
        lib.solve = reinterpret_cast<SolveMs>(dlsym(h, "aerialShimSolveMs"));
        lib.destroy = reinterpret_cast<Destroy>(dlsym(h, "aerialShimDestroy"));
        if (create == nullptr || lib.solve == nullptr || lib.destroy == nullptr) {
            std::fprintf(stderr, "sky_against: %s is not a solver shim\n", argv[i]);
            return 1;
        }
        lib.solver = create(threads, std::atoi(argv[i + 1]));
        libs.push_back(lib);
    }
    const double suns[] = {-6.0,     -4.0, -2.0, -1.0, -0.5, -0.1, -0.002,
                           -0.00002, 0.0,  0.5,  2.0,  10.0, 30.0, 90.0};
    const std::size_t ns = sizeof suns / sizeof suns[0], nl = libs.size();
    std::vector<double> best(ns * nl, 1e30);
    for (int r = 0; r < rounds; ++r)
        for (std::size_t s = 0; s < ns; ++s)
            for (std::size_t l = 0; l < nl; ++l)
                best[s * nl + l] = std::min(best[s * nl + l], libs[l].solve(libs[l].solver, suns[s]));
    std::printf("best of %d solves [ms], %s threads\n%9s", rounds, threads == 0 ? "all" : argv[1], "sun");
    for (const Library& lib : libs) std::printf(" %16s", lib.name.c_str());
    std::printf("  each / the first\n");
    std::vector<double> worst(nl, 0.0);
    for (std::size_t s = 0; s < ns; ++s) {
        std::printf("%9.5f", suns[s]);
        for (std::size_t l = 0; l < nl; ++l) std::printf(" %16.3f", best[s * nl + l]);
        for (std::size_t l = 1; l < nl; ++l) {
            const double ratio = best[s * nl + l] / best[s * nl];
            worst[l] = std::max(worst[l], ratio);
            std::printf(" %5.2f", ratio);
        }
        std::printf("\n");
    }
    std::printf("%9s", "worst");
    for (std::size_t l = 0; l < nl; ++l) std::printf(" %16s", "");
    for (std::size_t l = 1; l < nl; ++l) std::printf(" %5.2f", worst[l]);
    std::printf("\n");
    for (const Library& lib : libs) lib.destroy(lib.solver);
    return 0;
}
