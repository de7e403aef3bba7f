// SPDX-License-Identifier: MIT
#include "soak/soak.hpp"

#include <libguile.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/guile_boot.hpp"
#include "common/org_file.hpp"
#include "common/run_info.hpp"


namespace bench {

namespace {

constexpr int kDefaultFrames = 1000000;
constexpr int kDefaultWarmup = 2000;
const char* const kDemos[] = {"platformer", "topdown", "sandbox", "shmup", "tweens"};

struct DemoRun {
    std::string name;
    std::string error;  // non-empty: the run failed
    std::string guile;  // Guile's version
    long frames = 0, warmup = 0, events = 0, sounds = 0;
    double seconds = 0;
    double heap_start = 0, heap_mid = 0, heap_end = 0, rss_start = 0, rss_mid = 0, rss_end = 0;  // bytes
};


struct Job {
    DemoRun* run;
    const char* file;  // no C++ object in run_demo: a Scheme error unwinds it without destructors
    long frames, warmup;
};

double number(SCM alist, const char* key) {
    SCM v = scm_assq_ref(alist, scm_from_utf8_symbol(key));
    return scm_is_real(v) ? scm_to_double(v) : 0;
}

SCM run_demo(void* data) {
    Job& job = *static_cast<Job*>(data);
    DemoRun& r = *job.run;
    SCM result = scm_call_6(scm_c_public_ref("bench soak", "soak-demo"), scm_from_utf8_string(job.file),
                            scm_from_long(job.frames), scm_from_utf8_keyword("warmup"), scm_from_long(job.warmup),
                            scm_from_utf8_keyword("page-size"), scm_from_long(sysconf(_SC_PAGESIZE)));
    r.frames = static_cast<long>(number(result, "frames"));
    r.warmup = static_cast<long>(number(result, "warmup"));
    r.seconds = number(result, "seconds");
    r.heap_start = number(result, "heap-start");
    r.heap_mid = number(result, "heap-mid");
    r.heap_end = number(result, "heap-end");
    r.rss_start = number(result, "rss-start");
    r.rss_mid = number(result, "rss-mid");
    r.rss_end = number(result, "rss-end");
    r.events = static_cast<long>(number(result, "events"));
    r.sounds = static_cast<long>(number(result, "sounds"));
    return SCM_BOOL_T;
}

SCM on_error(void* data, SCM key, SCM args) {
    Job& job = *static_cast<Job*>(data);
    job.run->error = error_text(key, args);
    return SCM_BOOL_F;
}

void* run_in_guile(void* data) {
    scm_c_catch(SCM_BOOL_T, run_demo, data, on_error, data, nullptr, nullptr);
    return nullptr;
}

double kib(double bytes) { return bytes / 1024; }

void print_header() {
    std::printf("%-10s %8s %8s %10s %10s %10s %10s %10s %10s %7s %7s\n", "demo", "frames", "s", "RSS KiB",
                "halfway", "end", "heap KiB", "halfway", "end", "events", "sounds");
    std::fflush(stdout);
}

void print_run(const DemoRun& r) {
    if (!r.error.empty()) {
        std::printf("%-10s error: %s\n", r.name.c_str(), r.error.c_str());
    } else {
        std::printf("%-10s %8ld %8.2f %10.0f %10.0f %10.0f %10.0f %10.0f %10.0f %7ld %7ld\n", r.name.c_str(),
                    r.frames, r.seconds, kib(r.rss_start), kib(r.rss_mid), kib(r.rss_end), kib(r.heap_start),
                    kib(r.heap_mid), kib(r.heap_end), r.events, r.sounds);
    }
    std::fflush(stdout);
}

// "start → halfway → end (±growth)", in KiB.
std::string change(double start, double mid, double end) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%.0f → %.0f → %.0f (%+.0f)", kib(start), kib(mid), kib(end), kib(end - start));
    return buf;
}

std::string fixed2(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

const char* const kBegin = "# BEGIN downstroke-bench soak";
const char* const kEnd = "# END downstroke-bench soak";

// What stays the same from run to run; written only into a new file.
const char* const kIntro =
    "#+TITLE: Downstroke — soak: the demos for a million frames\n\n"
    "Each demo (=demo/*.scm=) runs headless in the bench's Guile, in a process of its own (forked, "
    "so each starts from a fresh heap), its input script replayed every =demo-frames= frames. "
    "Memory is sampled after a full collection, after the warm-up, halfway and at the end: the "
    "resident set size (=/proc/self/statm=) and Guile's heap size (=(gc-stats)=). The demos keep a "
    "ring of their last 1000 frames and at most 1000 events; the engine's sound log (=game-sounds=) "
    "keeps the newest 4096 to 8192 sounds. A quick version (10^4 frames, with bounds) is part "
    "of the test suite: =tests/scheme/stress-test.scm=.\n\n";

std::string results(const RunInfo& info, const std::string& guile, long frames, long warmup,
                    const std::vector<DemoRun>& runs) {
    std::ostringstream o;
    o << kBegin << " (generated; edits here are overwritten)\n"
      << frames << " frames a demo, " << warmup << " of them warm-up. Measured " << info.date << ", "
      << info.cores << " cores (" << info.cpu << "), Guile " << guile << ", "
      << (info.build_type.empty() ? "no build type" : info.build_type) << " build:\n\n"
      << "#+begin_src sh\n" << info.command << "\n#+end_src\n\n"
      << "| demo | frames | s | RSS KiB | heap KiB | events | sounds |\n"
      << "|------+--------+---+---------+----------+--------+--------|\n";
    for (const DemoRun& r : runs) {
        if (!r.error.empty()) {
            o << "| " << r.name << " | error: " << r.error << " |\n";
            continue;
        }
        o << "| " << r.name << " | " << r.frames << " | " << fixed2(r.seconds) << " | "
          << change(r.rss_start, r.rss_mid, r.rss_end) << " | " << change(r.heap_start, r.heap_mid, r.heap_end)
          << " | " << r.events << " | " << r.sounds << " |\n";
    }
    o << "\nMemory: after the warm-up → halfway → at the end (growth over the run). s: the frames' time, "
      << "warm-up included. events, sounds: what the demo's event list and the game's sound log hold at "
      << "the end.\n"
      << kEnd << "\n";
    return o.str();
}

// Replaces the generated block of an existing file (keeping the notes around
// it), or writes a new document.
void write_org(const std::string& file, const RunInfo& info, const std::string& guile, long frames, long warmup,
               const std::vector<DemoRun>& runs) {
    write_generated(file, kBegin, kEnd, results(info, guile, frames, warmup, runs), kIntro);
}

// The run as "key value" lines, for the parent.
std::string encode(const DemoRun& r) {
    std::ostringstream o;
    o.precision(17);
    std::string error = r.error;
    for (char& c : error)
        if (c == '\n' || c == '\r') c = ' ';
    o << "guile " << r.guile << "\nframes " << r.frames << "\nwarmup " << r.warmup << "\nseconds " << r.seconds
      << "\nheap " << r.heap_start << ' ' << r.heap_mid << ' ' << r.heap_end << "\nrss " << r.rss_start << ' '
      << r.rss_mid << ' ' << r.rss_end
      << "\nevents " << r.events << "\nsounds " << r.sounds << "\n";
    if (!error.empty()) o << "error " << error << "\n";
    return o.str();
}

void decode(const std::string& text, DemoRun& r) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        std::istringstream l(line);
        std::string key, rest;
        l >> key;
        std::getline(l >> std::ws, rest);
        std::istringstream v(rest);
        if (key == "guile") r.guile = rest;
        else if (key == "frames") v >> r.frames;
        else if (key == "warmup") v >> r.warmup;
        else if (key == "seconds") v >> r.seconds;
        else if (key == "heap") v >> r.heap_start >> r.heap_mid >> r.heap_end;
        else if (key == "rss") v >> r.rss_start >> r.rss_mid >> r.rss_end;
        else if (key == "events") v >> r.events;
        else if (key == "sounds") v >> r.sounds;
        else if (key == "error") r.error = rest;
    }
}

// One demo in a child process of its own, forked before this process ever
// boots Guile: each starts from a fresh heap, so a demo's figures do not
// carry the heap an earlier demo grew (or the pages it left untouched).
DemoRun run_forked(const std::string& name, long frames, long warmup) {
    DemoRun r;
    r.name = name;
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("soak: cannot create a pipe");
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("soak: cannot fork");
    if (pid == 0) {
        close(fds[0]);
        r.guile = guile_version();  // boots Guile: compiled modules only; soak.scm compiles the demo
        const std::string file = std::string(DS_BENCH_SOURCE_DIR) + "/demo/" + name + ".scm";
        Job job{&r, file.c_str(), frames, warmup};
        scm_with_guile(run_in_guile, &job);
        const std::string text = encode(r);
        for (size_t done = 0; done < text.size();) {
            const ssize_t n = write(fds[1], text.data() + done, text.size() - done);
            if (n <= 0) break;
            done += static_cast<size_t>(n);
        }
        close(fds[1]);
        std::fflush(stdout);
        _exit(0);
    }
    close(fds[1]);
    std::string out;
    char buf[4096];
    for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<size_t>(n));
    close(fds[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    decode(out, r);
    if (r.error.empty() && !(WIFEXITED(status) && WEXITSTATUS(status) == 0))
        r.error = "child process failed (status " + std::to_string(status) + ")";
    return r;
}

}  // namespace

int soak(const Options& opts) {
    const long frames = opts.frames > 0 ? opts.frames : kDefaultFrames;
    const long warmup = opts.warmup >= 0 ? opts.warmup : kDefaultWarmup;
    const RunInfo info = collect_run_info(opts.command);
    std::printf("soak: %ld frames a demo (warm-up %ld), each in a process of its own, %d cores\n", frames, warmup,
                info.cores);
    print_header();
    std::vector<DemoRun> runs;
    std::string guile;
    for (const char* name : kDemos) {
        runs.push_back(run_forked(name, frames, warmup));
        print_run(runs.back());
        if (guile.empty()) guile = runs.back().guile;
    }
    if (!opts.org.empty()) write_org(opts.org, info, guile, frames, warmup, runs);
    for (const DemoRun& r : runs)
        if (!r.error.empty()) return EXIT_FAILURE;
    return EXIT_SUCCESS;
}

}  // namespace bench
