// SPDX-License-Identifier: MIT
// The seeded sensitivity sweep of the scan fit's end-stray check (studies::EndStrayCheck: the quadratic's
// window of inward points and the outermost points judged at each end). Every (window, judged) cell fits the
// same clouds from five generators — hula::testing's scanned_cloud and simulate_scan, and the Bézier/Gaussian,
// wave/Laplace and tail (contaminated-normal, gaps) generators of scan_test_clouds.hpp — in order, shuffled and
// reversed, σ 0.01–0.1 of the tolerance, 1 % strays, and in three clouds of four a stray at an end of the
// curve 2–30 tolerances off, and judges each by the criteria of issue 21 (test_clouds::judge). It prints the
// pass count per cell and, per cell, what failed. Not a test (minutes of CPU): docs/studies.md, "End strays".
//
//   scan_fit_end_sweep [--per N] [--windows 4,5,...] [--judged 2,3,...] [--list] [--known-order]
//
// --per: clouds per generator (default 12); --list: print every failing cloud of every cell; --known-order:
// each cloud is first sorted by its points' feet on the known curve and fitted with ScanFitOptions::ordered,
// so that a cloud failing without it and passing with it fails by its ordering, not by the fit.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "hula/studies/scan_fit.hpp"
#include "scan_test_clouds.hpp"

namespace {

using namespace hula;  // NOLINT(google-build-using-namespace): a small tool
using studies::test_clouds::Order;
using studies::test_clouds::TestCloud;

std::vector<std::size_t> parse_list(std::string_view s) {
  std::vector<std::size_t> out;
  std::stringstream in{std::string(s)};
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(static_cast<std::size_t>(std::stoul(item)));
  return out;
}

// Cloud k of a generator: order k % 3, end stray by k / 3 % 4 (none; the first point 2–30 tolerances off;
// the last 2–30; the first or the last 2–4), σ / tol 0.01, 0.03, 0.1 cycled, shapes and sizes cycled.
struct EndStray {
  double off = 0.0;
  bool last = false;
};

EndStray end_stray(std::size_t k, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  switch (k / 3 % 4) {
    case 1:
      return {2.0 * std::pow(15.0, u(rng)), false};
    case 2:
      return {2.0 * std::pow(15.0, u(rng)), true};
    case 3:
      return {2.0 + 2.0 * u(rng), k % 2 == 1};
    default:
      return {};
  }
}

// The cloud sorted by its points' feet on the known curve (strays tracked through the permutation).
TestCloud in_known_order(const TestCloud& c) {
  std::vector<double> t(c.points.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = c.known_foot(c.points[i]).t;
  std::vector<std::size_t> perm(t.size());
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  std::stable_sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) { return t[a] < t[b]; });
  TestCloud out = c;
  out.strays.clear();
  for (std::size_t j = 0; j < perm.size(); ++j) {
    out.points[j] = c.points[perm[j]];
    if (std::binary_search(c.strays.begin(), c.strays.end(), perm[j])) out.strays.push_back(j);
  }
  std::sort(out.strays.begin(), out.strays.end());
  out.name += ", known order";
  return out;
}

std::vector<TestCloud> make_clouds(std::size_t per) {
  namespace tc = studies::test_clouds;
  const double sigmas[] = {0.01, 0.03, 0.1};
  std::vector<TestCloud> out;
  for (std::size_t k = 0; k < per; ++k) {
    const auto order = static_cast<Order>(k % 3);
    const double sigma = sigmas[(k + k / 3) % 3];
    const std::uint64_t seed = 5000 + k;
    const EndStray e = end_stray(k, seed);
    const std::string tag =
        std::string(", ") + tc::order_name(order) + ", σ/tol " + std::to_string(sigma) +
        (e.off > 0.0 ? ", " + std::string(e.last ? "last" : "first") + " point " + std::to_string(e.off) + " tol off"
                     : std::string(", no end stray"));
    // 1. hula::testing::scanned_cloud
    {
      const testing::KnownCurve shapes[] = {testing::KnownCurve::Arc, testing::KnownCurve::SCurve,
                                            testing::KnownCurve::Wave};
      const std::size_t counts[] = {500, 1000, 2000};
      TestCloud c =
          tc::scanned_test_cloud(shapes[(k + k / 3) % 3], counts[k / 2 % 3], sigma, order, e.off, e.last, seed);
      c.name += ", " + std::to_string(c.points.size()) + " points" + tag;
      out.push_back(std::move(c));
    }
    // 2. and 3. Bézier/Gaussian and wave/Laplace
    for (const tc::Generator g : {tc::Generator::BezierGaussian, tc::Generator::WaveLaplace}) {
      const double sizes[] = {1.0, 10.0, 100.0, 1000.0};
      const std::size_t counts[] = {300, 1000, 2000};
      const tc::Case c{g, k % 2 == 0, k / 2 % 2 == 1, order, sizes[k % 4], counts[k / 4 % 3], sigma, e.off, e.last};
      TestCloud t = tc::foreign_cloud(c, seed);
      t.name += ", size " + std::to_string(c.size) + ", " + std::to_string(c.points) + " points" + tag;
      out.push_back(std::move(t));
    }
    // 4. hula::testing::simulate_scan
    {
      const testing::ScanShape shapes[] = {testing::ScanShape::SCubic, testing::ScanShape::Convex,
                                           testing::ScanShape::Quartic, testing::ScanShape::TwistedCubic,
                                           testing::ScanShape::Helix};
      const testing::ScanNoise noises[] = {testing::ScanNoise::Uniform, testing::ScanNoise::StudentT,
                                           testing::ScanNoise::Anisotropic, testing::ScanNoise::Depth};
      const double sizes[] = {1.0, 100.0, 1000.0};
      const std::size_t counts[] = {400, 1000, 2000};
      TestCloud t = tc::simulated_test_cloud(shapes[k % 5], noises[k % 4], sizes[k % 3], counts[k / 3 % 3], sigma,
                                             order, e.off, e.last, seed);
      t.name += ", size " + std::to_string(sizes[k % 3]) + ", " + std::to_string(counts[k / 3 % 3]) + " points" + tag;
      out.push_back(std::move(t));
    }
    // 5. the tail generator
    {
      const tc::TailShape shapes[] = {tc::TailShape::Spiral, tc::TailShape::Step, tc::TailShape::ConicalHelix};
      const double sizes[] = {1.0, 1000.0, 10.0, 100.0};
      const std::size_t counts[] = {300, 1000, 2000};
      const tc::TailCase c{shapes[(k + k / 3) % 3], order, sizes[k % 4], counts[k / 4 % 3], sigma, e.off, e.last};
      TestCloud t = tc::make_tail_cloud(c, seed);
      t.name += ", size " + std::to_string(c.size) + ", " + std::to_string(c.points) + " points" + tag;
      out.push_back(std::move(t));
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t per = 12;
  std::vector<std::size_t> windows{4, 5, 6, 7, 8, 9, 10, 11, 12}, judged{2, 3, 4, 5};
  bool list = false, known_order = false;
  for (int i = 1; i < argc; ++i) {
    const std::string_view a = argv[i];
    if (a == "--per" && i + 1 < argc)
      per = std::stoul(argv[++i]);
    else if (a == "--windows" && i + 1 < argc)
      windows = parse_list(argv[++i]);
    else if (a == "--judged" && i + 1 < argc)
      judged = parse_list(argv[++i]);
    else if (a == "--list")
      list = true;
    else if (a == "--known-order")
      known_order = true;
    else {
      std::fprintf(stderr, "usage: %s [--per N] [--windows 4,5,...] [--judged 2,3,...] [--list] [--known-order]\n",
                   argv[0]);
      return 2;
    }
  }
  std::vector<TestCloud> clouds = make_clouds(per);
  if (known_order)
    for (TestCloud& c : clouds) c = in_known_order(c);
  std::printf("%zu clouds (%zu per generator), %zu cells\n", clouds.size(), per, windows.size() * judged.size());
  std::printf("window judged  pass/total  missed-stray good-rejected beyond-3σ inflections threw  seconds\n");
  for (const std::size_t w : windows)
    for (const std::size_t j : judged) {
      studies::ScanFitOptions o;
      o.end_check = {.window = w, .judged = j};
      o.ordered = known_order;
      std::size_t pass = 0, missed = 0, rejected = 0, far = 0, infl = 0, threw = 0;
      std::vector<std::string> failures;
      std::map<std::string, std::size_t> sources;  // how many clouds each ordering took
      const auto t0 = std::chrono::steady_clock::now();
      for (const TestCloud& c : clouds) {
        o.tolerance = c.tolerance;
        studies::test_clouds::Verdict v;
        const char* ordering = "";
        try {
          const studies::ScanFitResult r = studies::fit_scan(c.points, o);
          v = studies::test_clouds::judge(c, r);
          ordering = studies::order_source_name(r.ordering);
          ++sources[ordering];
        } catch (const std::exception& e) {
          v.threw = true;
          v.error = e.what();
        }
        if (v.pass(c.sigma)) {
          ++pass;
          continue;
        }
        missed += v.strays_missed > 0;
        rejected += v.good_rejected > 0;
        far += v.far > 3.0 * c.sigma;
        infl += !v.inflections_right;
        threw += v.threw;
        char line[512];
        std::snprintf(line, sizeof line,
                      "  %s: missed %zu, good rejected %zu, far %.3g σ, inflections %zu (%zu), order %s%s%s",
                      c.name.c_str(), v.strays_missed, v.good_rejected, v.far / c.sigma, v.inflections,
                      v.known_inflections, ordering, v.threw ? ", threw: " : "", v.error.c_str());
        failures.emplace_back(line);
      }
      const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("%6zu %6zu  %4zu/%-4zu   %12zu %13zu %9zu %11zu %5zu  %7.1f\n", w, j, pass, clouds.size(), missed,
                  rejected, far, infl, threw, secs);
      std::printf("       orders:");
      for (const auto& [name, count] : sources) std::printf(" %s %zu", name.c_str(), count);
      std::printf("\n");
      if (list)
        for (const std::string& f : failures) std::printf("%s\n", f.c_str());
      std::fflush(stdout);
    }
  return 0;
}
