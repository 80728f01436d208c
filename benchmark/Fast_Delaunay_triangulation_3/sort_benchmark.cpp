// Spatial sort layer (paper §2.3) beside the alternatives: our BRIO order (keys + radix sort) against std::sort on
// the same (key, value) pairs and against CGAL::spatial_sort of Epick points, on uniform random points.
// Engines run interleaved within each repetition; the table shows medians of 5 in milliseconds.
//
// Usage: sort_benchmark [n ...]   (default 1e5 1e6 1e7)

#include <CGAL/Fast_Delaunay_triangulation_3/internal/BRIO.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <thread>
#include <vector>

namespace fdt = CGAL::Fast_Delaunay_triangulation_3_internal;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Item = fdt::Key_value<std::uint32_t>;

namespace {

constexpr int repetitions = 5;

template <class Function>
double milliseconds(const Function& f)
{
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Read by the end of main so that no timed result can be optimised away.
std::uint64_t checksum = 0;

struct Row
{
  std::vector<double> brio_1, brio_2, brio_keys_1, radix_1, radix_2, std_sort, cgal_1, cgal_2;
  int key_bits = 0;
};

Row measure(std::size_t n)
{
  std::mt19937_64 random(n);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  std::vector<double> xyz(3 * n);
  for(double& c : xyz)
    c = coordinate(random);
  std::vector<Kernel::Point_3> points;
  points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    points.emplace_back(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);

  Row row;
  for(int rep = 0; rep < repetitions; ++rep) {
    const std::uint64_t seed = std::uint64_t(rep);
    // One-shot calls: allocation of every buffer is inside the time, as a first triangulation would pay it.
    for(int threads : {1, 2}) {
      fdt::Brio_order result;
      const double t = milliseconds([&] { result = fdt::brio_order(xyz.data(), n, seed, threads); });
      (threads == 1 ? row.brio_1 : row.brio_2).push_back(t);
      checksum += result.order[n / 2] + result.round_end.size();
    }

    std::vector<Item> keys;
    fdt::Brio_key_layout layout;
    row.brio_keys_1.push_back(milliseconds([&] { layout = fdt::brio_keys(xyz.data(), n, seed, 1, keys); }));
    row.key_bits = layout.key_bits;

    // The sorts alone, on the same keys, with the second buffer already allocated.
    std::vector<Item> items, scratch(n);
    for(int threads : {1, 2}) {
      items = keys;
      const double t = milliseconds([&] { fdt::radix_sort(items, scratch, layout.key_bits, threads); });
      (threads == 1 ? row.radix_1 : row.radix_2).push_back(t);
      checksum += items[n / 2].value;
    }
    items = keys;
    row.std_sort.push_back(milliseconds([&] {
      std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
    }));
    checksum += items[n / 2].value;

    std::vector<Kernel::Point_3> copy = points;
    row.cgal_1.push_back(milliseconds([&] { CGAL::spatial_sort(copy.begin(), copy.end()); }));
    checksum += std::uint64_t(copy[n / 2].x() * 1e6);
#ifdef CGAL_LINKED_WITH_TBB
    copy = points;
    row.cgal_2.push_back(milliseconds([&] { CGAL::spatial_sort<CGAL::Parallel_tag>(copy.begin(), copy.end()); }));
    checksum += std::uint64_t(copy[n / 2].x() * 1e6);
#endif
  }
  return row;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::size_t> sizes;
  for(int k = 1; k < argc; ++k)
    sizes.push_back(std::size_t(std::strtod(argv[k], nullptr)));
  if(sizes.empty())
    sizes = {100000, 1000000, 10000000};

  std::printf("spatial sort of uniform random points in the unit cube; median of %d runs, milliseconds\n", repetitions);
  std::printf("hardware threads: %u; TBB: %s; 'T' = threads given to the sort\n", std::thread::hardware_concurrency(),
#ifdef CGAL_LINKED_WITH_TBB
              "yes"
#else
              "no (the 2-thread columns run sequentially)"
#endif
  );
  std::printf("brio = brio_order (keys + radix sort + order), keys = brio_keys alone, radix/std::sort on the same "
              "(key, index) pairs, CGAL = CGAL::spatial_sort (Epick Point_3)\n\n");
  std::printf("%10s %9s %9s %9s %9s %9s %9s %10s %9s %9s %11s\n", "n", "key bits", "brio 1T", "brio 2T", "keys 1T",
              "radix 1T", "radix 2T", "std::sort", "CGAL 1T", "CGAL 2T", "CGAL/brio");
  for(std::size_t n : sizes) {
    const Row row = measure(n);
    std::printf("%10zu %9d %9.2f %9.2f %9.2f %9.2f %9.2f %10.2f %9.2f ", n, row.key_bits, median(row.brio_1),
                median(row.brio_2), median(row.brio_keys_1), median(row.radix_1), median(row.radix_2),
                median(row.std_sort), median(row.cgal_1));
    if(row.cgal_2.empty())
      std::printf("%9s", "-");
    else
      std::printf("%9.2f", median(row.cgal_2));
    std::printf(" %11.1f\n", median(row.cgal_1) / median(row.brio_1));
    std::fflush(stdout);
  }
  std::printf("\n(checksum %llu)\n", static_cast<unsigned long long>(checksum % 1000));
  return 0;
}
