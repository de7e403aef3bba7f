// SPDX-License-Identifier: MIT
#include "accuracy/plot.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace bench::accuracy {

namespace {

bool have_gnuplot() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

// A gnuplot data block of (ms/frame, error, k) for the rows one curve takes.
template <class Pick, class Error>
std::string block(const std::string& name, const std::vector<Row>& rows, Pick pick, Error error) {
    std::ostringstream o;
    o << "$" << name << " << EOD\n";
    for (const Row& r : rows)
        if (pick(r)) o << r.arena.median_ms << " " << error(r) << " k=" << r.cfg.k << "\n";
    return o.str() + "EOD\n";
}

std::string quoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
    return q + "'";
}

// Discrete and swept land on the same points wherever nothing outruns a
// tile, so only the swept curves carry the k labels.
std::string curve(const std::string& block, const std::string& title, int style, bool labels) {
    std::string s = "$" + block + " using 1:2 with linespoints ls " + std::to_string(style) + " title '" + title + "'";
    if (labels) s += ", $" + block + " using 1:2:3 with labels offset char 0,0.8 font ',8' notitle";
    return s;
}

std::string data(const std::vector<Row>& rows) {
    using M = ds::CollisionMode;
    auto traj = [](const Row& r) { return r.traj.max_error; };
    auto inside = [](const Row& r) { return 100 * r.arena.inside_share(); };
    auto is = [](M m, bool rest) { return [=](const Row& r) { return r.cfg.mode == m && r.cfg.resting == rest; }; };
    return block("traj_discrete", rows, is(M::Discrete, false), traj) + block("traj_swept", rows, is(M::Swept, false), traj) +
           block("in_discrete_off", rows, is(M::Discrete, false), inside) + block("in_swept_off", rows, is(M::Swept, false), inside) +
           block("in_discrete_on", rows, is(M::Discrete, true), inside) + block("in_swept_on", rows, is(M::Swept, true), inside);
}

std::string script(const std::string& png, const std::vector<Row>& rows) {
    std::ostringstream o;
    o << data(rows)
      << "set terminal pngcairo size 1200,520 font 'sans,10'\n"
      << "set output " << quoted(png) << "\n"
      << "set style line 1 lc rgb '#c0392b' lw 2 pt 7\nset style line 2 lc rgb '#2471a3' lw 2 pt 5\n"
      << "set style line 3 lc rgb '#e6a09a' lw 2 pt 6 dt 2\nset style line 4 lc rgb '#8fb8de' lw 2 pt 4 dt 2\n"
      << "set multiplot layout 1,2 title 'Downstroke: error against cost, k = 1, 2, 4, 8 sub-frames'\n"
      << "set grid\nset logscale x\nset xlabel 'ms per frame (arena scene, median)'\n"
      << "set logscale y\nset ylabel 'largest |y - y_{exact}| of a jump, px'\n"
      << "set title 'Trajectory (resting contacts off; on is the same)'\n"
      << "plot " << curve("traj_discrete", "discrete", 1, false) << ", " << curve("traj_swept", "swept", 2, true) << "\n"
      << "set ylabel 'body-frames ending inside a solid, %'\n"
      << "set title 'Penetration (arena scene)'\n"
      << "plot " << curve("in_discrete_off", "discrete", 1, false) << ", " << curve("in_swept_off", "swept", 2, true)
      << ", " << curve("in_discrete_on", "discrete, resting contacts", 3, false) << ", "
      << curve("in_swept_on", "swept, resting contacts", 4, true) << "\n"
      << "unset multiplot\n";
    return o.str();
}

}  // namespace

PlotResult write_plot(const std::string& png, const std::vector<Row>& rows) {
    if (!have_gnuplot()) return {false, "skipped: gnuplot is not installed (apt-get install gnuplot-nox)"};
    std::FILE* p = popen("gnuplot", "w");
    if (!p) return {false, "skipped: gnuplot could not be started"};
    const std::string s = script(png, rows);
    std::fwrite(s.data(), 1, s.size(), p);
    const int status = pclose(p);
    if (status != 0)
        return {false, "failed: gnuplot exited with status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : status)};
    return {true, "written to " + png};
}

}  // namespace bench::accuracy
