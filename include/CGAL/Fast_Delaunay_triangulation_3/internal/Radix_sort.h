// Stable radix sort of (64-bit key, value) pairs, sequential or split over threads: least significant digit first
// while the array fits in cache, most significant digit first beyond (measured at 1e7 BRIO keys of 63 bits, 2
// threads: 343 ms LSD, 210 ms MSD; 1e6: 18.7 ms, 13.7 ms).
//
// Paper §2.3 ("Fast spatial sorting"): Moore indices are short bounded integers, so sorting digit by digit costs
// O(key bits x n) and beats comparison sorts; the keys here carry ~30 significant bits for 1e6 points instead of
// HXT's 63 (HXT_FACTS §2, §7 idea 7), so fewer passes. Also the small chunking helpers the rest of the sort layer runs its loops with.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_RADIX_SORT_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_RADIX_SORT_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// A default-constructed item is left unwritten: the buffers of millions of
// items (BRIO's keys and the sort's second buffer) are sized before the
// chunked loops fill them, and zeroing them first made one thread fault in
// and clear all their pages.
template <class Value>
struct Key_value
{
  std::uint64_t key;
  Value value;

  Key_value() noexcept {}
  Key_value(std::uint64_t k, const Value& v) noexcept : key(k), value(v) {}
};

// Below this many items per chunk, waking a second thread costs more than the loop it would share.
constexpr std::size_t min_items_per_chunk = std::size_t(1) << 14;

// How many contiguous chunks to cut n items into for a loop run on `num_threads` threads.
inline int chunk_count(std::size_t n, int num_threads)
{
  const std::size_t useful = std::max<std::size_t>(1, n / min_items_per_chunk);
  return int(std::min<std::size_t>(std::size_t(std::max(num_threads, 1)), useful));
}

// chunk_count(n, num_threads), lowered so that the chunks' own buffers,
// `chunk_bytes` each, take at most `budget_bytes` (one chunk at least): for
// loops whose chunks each hold an entry per vertex.
inline int chunk_count_within(std::size_t n, int num_threads, std::size_t chunk_bytes, std::size_t budget_bytes)
{
  const std::size_t affordable = std::max<std::size_t>(1, budget_bytes / std::max<std::size_t>(chunk_bytes, 1));
  return int(std::min<std::size_t>(std::size_t(chunk_count(n, num_threads)), affordable));
}

// First item of chunk c when n items are cut into `chunks` contiguous pieces whose sizes differ by at most one.
inline std::size_t chunk_begin(std::size_t n, int chunks, int c)
{
  return n / std::size_t(chunks) * std::size_t(c) + std::min(std::size_t(c), n % std::size_t(chunks));
}

// Calls f(c) for every chunk c in [0, chunks): concurrently with TBB, in order without it. Callers make each chunk's
// work independent of the others, so results do not depend on which of the two ran.
// Under ThreadSanitizer the chunks run on std::threads instead: TBB's library is
// not instrumented, so the sanitizer cannot see that its parallel_for joins
// the tasks and reports the caller's reads of their results as races.
template <class Function>
void for_each_chunk(int chunks, const Function& f)
{
#if defined(__SANITIZE_THREAD__)
  if(chunks > 1) {
    // An exception must not leave a std::thread (that terminates): each
    // chunk's is kept, and the first chunk's rethrown after the joins.
    std::vector<std::exception_ptr> errors(chunks);
    auto run = [&f, &errors](int c) {
      try {
        f(c);
      } catch(...) {
        errors[c] = std::current_exception();
      }
    };
    std::vector<std::thread> threads;
    for(int c = 1; c < chunks; ++c) threads.emplace_back(run, c);
    run(0);
    for(std::thread& t : threads) t.join();
    for(const std::exception_ptr& e : errors)
      if(e) std::rethrow_exception(e);
    return;
  }
#elif defined(CGAL_LINKED_WITH_TBB)
  if(chunks > 1) {
    tbb::parallel_for(0, chunks, [&](int c) { f(c); });
    return;
  }
#endif
  for(int c = 0; c < chunks; ++c)
    f(c);
}

// Calls f(begin, end) for the contiguous ranges that cut [0, n) into
// chunk_count(n, num_threads) chunks, as for_each_chunk runs them.
template <class Function>
void for_each_range(std::size_t n, int num_threads, const Function& f)
{
  const int chunks = chunk_count(n, num_threads);
  for_each_chunk(chunks, [&](int c) { f(chunk_begin(n, chunks, c), chunk_begin(n, chunks, c + 1)); });
}

namespace radix_detail {

constexpr std::size_t insertion_sort_limit = 64;

// Digit widths, measured on the 2-core Xeon VM this package is developed on (16-byte items, 1e6..1e7 BRIO keys):
// - one thread scattering out of cache pays per write stream: 3.7 ns/item with <= 64 buckets, 10-12 ns/item with
//   128..2048 (huge pages did not change it), so 6-bit digits win despite more passes (1e6 keys of 30 bits: 16 ms
//   with 6-bit digits, 26 ms with 11-bit; 1e7 keys of 33 bits: 240 ms against 371 ms);
// - two threads saturate memory bandwidth (6-bit digits: 15.6 ms on 2 threads vs 16.0 ms on 1), so there the fewest
//   passes win: 11-bit digits, 11.7 ms;
// - data that stays in cache (both buffers within ~1 MiB) is cheap to scatter either way: fewest passes.
constexpr int wide_digit_bits = 11;
constexpr int narrow_digit_bits = 6;
constexpr std::size_t in_cache_bytes = std::size_t(1) << 20;

struct Digit_plan
{
  int passes;
  int bits;
};

// The fewest passes of at most max_bits, then equal digits: 27 bits -> 3 x 9 (wide) or 5 x 6 (narrow).
inline Digit_plan plan_digits(int key_bits, int max_bits)
{
  const int passes = (key_bits + max_bits - 1) / max_bits;
  return {passes, (key_bits + passes - 1) / passes};
}

// The counting sort step both directions share: `offset` holds the count of
// every digit of the n source items; it becomes their first positions, the
// items go to target in a stable order, and `offset` ends holding where every
// digit's run ends.
template <class Value, class Count>
void scatter_by_digit(const Key_value<Value>* source, Key_value<Value>* target, std::size_t n, int shift,
                      std::uint64_t mask, Count* offset, std::size_t buckets)
{
  Count sum = 0;
  for(std::size_t d = 0; d < buckets; ++d)
    sum += std::exchange(offset[d], sum);
  for(std::size_t i = 0; i < n; ++i)
    target[offset[(source[i].key >> shift) & mask]++] = source[i];
}

template <class Value>
void insertion_sort(std::vector<Key_value<Value>>& items)
{
  for(std::size_t i = 1; i < items.size(); ++i) {
    Key_value<Value> item = items[i];
    std::size_t j = i;
    // Strict comparison: an item never passes an equal key, which is what makes the sort stable.
    for(; j > 0 && item.key < items[j - 1].key; --j)
      items[j] = items[j - 1];
    items[j] = item;
  }
}

template <class Value>
void sort_sequential(std::vector<Key_value<Value>>& items, std::vector<Key_value<Value>>& scratch, Digit_plan plan)
{
  const std::size_t n = items.size();
  const std::size_t buckets = std::size_t(1) << plan.bits;
  const std::uint64_t mask = buckets - 1;
  std::vector<std::size_t> count(std::size_t(plan.passes) * buckets, 0);
  // A pass permutes the items but keeps the multiset of every digit, so one read fills all passes' histograms.
  for(const Key_value<Value>& item : items)
    for(int p = 0; p < plan.passes; ++p)
      ++count[std::size_t(p) * buckets + ((item.key >> (p * plan.bits)) & mask)];

  Key_value<Value>* source = items.data();
  Key_value<Value>* target = scratch.data();
  for(int p = 0; p < plan.passes; ++p) {
    const int shift = p * plan.bits;
    std::size_t* offset = &count[std::size_t(p) * buckets];
    // When every item has the same digit the pass would only copy (e.g. the high digits of small coordinates).
    if(offset[(source[0].key >> shift) & mask] == n)
      continue;
    scatter_by_digit(source, target, n, shift, mask, offset, buckets);
    std::swap(source, target);
  }
  if(source != items.data())
    items.swap(scratch);
}

// Each chunk counts and scatters its own contiguous range. Output offsets are laid out digit-major, chunk-minor, so
// equal digits keep their input order across chunks: the result is the sequential sort's, item for item.
template <class Value>
void sort_chunked(std::vector<Key_value<Value>>& items, std::vector<Key_value<Value>>& scratch, Digit_plan plan,
                  int chunks)
{
  const std::size_t n = items.size();
  const std::size_t buckets = std::size_t(1) << plan.bits;
  const std::uint64_t mask = buckets - 1;
  std::vector<std::size_t> count(std::size_t(chunks) * buckets);

  Key_value<Value>* source = items.data();
  Key_value<Value>* target = scratch.data();
  for(int p = 0; p < plan.passes; ++p) {
    const int shift = p * plan.bits;
    for_each_chunk(chunks, [&](int c) {
      std::size_t* histogram = &count[std::size_t(c) * buckets];
      std::fill(histogram, histogram + buckets, std::size_t(0));
      const std::size_t end = chunk_begin(n, chunks, c + 1);
      for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i)
        ++histogram[(source[i].key >> shift) & mask];
    });
    bool copy_only = false;
    std::size_t sum = 0;
    for(std::size_t b = 0; b < buckets; ++b) {
      const std::size_t bucket_start = sum;
      for(int c = 0; c < chunks; ++c)
        sum += std::exchange(count[std::size_t(c) * buckets + b], sum);
      copy_only = copy_only || sum - bucket_start == n;
    }
    if(copy_only)
      continue;
    for_each_chunk(chunks, [&](int c) {
      std::size_t* offset = &count[std::size_t(c) * buckets];
      const std::size_t end = chunk_begin(n, chunks, c + 1);
      for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i)
        target[offset[(source[i].key >> shift) & mask]++] = source[i];
    });
    std::swap(source, target);
  }
  if(source != items.data())
    items.swap(scratch);
}

// Most significant digit first, for arrays far larger than the caches: one pass over the whole array splits it
// by the top digit into buckets that fit in cache, and each bucket is sorted there on its own, digit after digit,
// only as deep as its keys differ (buckets of a few dozen items end in an insertion sort). LSD would stream the
// whole array through memory once per digit: 6 times for BRIO's 63-bit keys. Stable like LSD (each scatter keeps
// the order of equal digits, the insertion sort never passes an equal key), hence the same result item for item.
constexpr int top_digit_bits = 11;
constexpr std::size_t msd_min_items = std::size_t(1) << 16;

// Digit width for a bucket of n items: about n / 4 buckets, between 4 and 11 bits.
inline int msd_digit_bits(std::size_t n, int remaining_bits)
{
  int bits = 4;
  while(bits < wide_digit_bits && (std::size_t(4) << bits) < n)
    ++bits;
  return std::min(bits, remaining_bits);
}

// Sorts the n items of a bucket by the low `shift` bits of their keys (the bits above are equal). The items are in
// `in_a ? a : b`; the result goes to a. a and b are the same range of the two buffers.
template <class Value>
void msd_sort_bucket(Key_value<Value>* a, Key_value<Value>* b, std::size_t n, int shift, bool in_a)
{
  Key_value<Value>* source = in_a ? a : b;
  Key_value<Value>* target = in_a ? b : a;
  while(true) {
    if(n <= insertion_sort_limit || shift == 0) {
      for(std::size_t i = 1; i < n; ++i) {
        const Key_value<Value> item = source[i];
        std::size_t j = i;
        for(; j > 0 && item.key < source[j - 1].key; --j)
          source[j] = source[j - 1];
        source[j] = item;
      }
      if(source != a)
        std::copy(source, source + n, a);
      return;
    }
    const int bits = msd_digit_bits(n, shift);
    shift -= bits;
    const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
    // One array per level (8 KiB of stack; the recursion goes one level per
    // digit where a bucket keeps more than insertion_sort_limit items): the
    // counts, then the offsets, then, after the scatter, the bucket ends.
    std::uint32_t offset[std::size_t(1) << wide_digit_bits];
    const std::size_t buckets = std::size_t(1) << bits;
    std::fill(offset, offset + buckets, 0u);
    for(std::size_t i = 0; i < n; ++i)
      ++offset[(source[i].key >> shift) & mask];
    // One digit for all: nothing to move, look at the next one.
    if(offset[(source[0].key >> shift) & mask] == n)
      continue;
    scatter_by_digit(source, target, n, shift, mask, offset, buckets);
    const bool target_is_a = target == a;
    std::size_t begin = 0;
    for(std::size_t d = 0; d < buckets; ++d) {
      const std::size_t end = offset[d];
      if(end > begin)
        msd_sort_bucket(a + begin, b + begin, end - begin, shift, target_is_a);
      begin = end;
    }
    return;
  }
}

// The top digit over contiguous chunks (histograms and scatter as in sort_chunked), then the buckets in groups of
// about equal size, one group per chunk.
template <class Value>
void sort_msd(std::vector<Key_value<Value>>& items, std::vector<Key_value<Value>>& scratch, int key_bits, int chunks)
{
  const std::size_t n = items.size();
  const int bits = std::min(top_digit_bits, key_bits);
  const int shift = key_bits - bits;
  const std::size_t buckets = std::size_t(1) << bits;
  const std::uint64_t mask = buckets - 1;
  std::vector<std::size_t> count(std::size_t(chunks) * buckets);
  const Key_value<Value>* source = items.data();
  Key_value<Value>* target = scratch.data();
  for_each_chunk(chunks, [&](int c) {
    std::size_t* histogram = &count[std::size_t(c) * buckets];
    const std::size_t end = chunk_begin(n, chunks, c + 1);
    for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i)
      ++histogram[(source[i].key >> shift) & mask];
  });
  std::vector<std::size_t> bucket_begin(buckets + 1);
  std::size_t sum = 0;
  for(std::size_t d = 0; d < buckets; ++d) {
    bucket_begin[d] = sum;
    for(int c = 0; c < chunks; ++c)
      sum += std::exchange(count[std::size_t(c) * buckets + d], sum);
  }
  bucket_begin[buckets] = n;
  for_each_chunk(chunks, [&](int c) {
    std::size_t* offset = &count[std::size_t(c) * buckets];
    const std::size_t end = chunk_begin(n, chunks, c + 1);
    for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i)
      target[offset[(source[i].key >> shift) & mask]++] = source[i];
  });
  // Group c: the buckets that start in [c n / chunks, (c + 1) n / chunks).
  for_each_chunk(chunks, [&](int c) {
    const std::size_t from = chunk_begin(n, chunks, c), to = chunk_begin(n, chunks, c + 1);
    for(std::size_t d = 0; d < buckets; ++d) {
      const std::size_t begin = bucket_begin[d], size = bucket_begin[d + 1] - begin;
      if(size > 0 && begin >= from && begin < to)
        msd_sort_bucket(items.data() + begin, scratch.data() + begin, size, shift, false);
    }
  });
}

} // namespace radix_detail

// Stable sort of `items` by key, ascending. Only the low `key_bits` bits of the keys may be non-zero. `scratch` is
// the second buffer of the ping-pong between passes; both vectors may trade their storage (the sorted data always
// ends in `items`, and `scratch` ends with items.size() elements of unspecified content). With num_threads > 1 the
// passes run on contiguous chunks in parallel (TBB), with exactly the same result as num_threads == 1.
template <class Value>
void radix_sort(std::vector<Key_value<Value>>& items, std::vector<Key_value<Value>>& scratch, int key_bits,
                int num_threads = 1)
{
  CGAL_precondition(key_bits >= 0 && key_bits <= 64);
  const std::size_t n = items.size();
  if(n < radix_detail::insertion_sort_limit) {
    radix_detail::insertion_sort(items);
    return;
  }
  CGAL_precondition(key_bits == 64 || std::all_of(items.begin(), items.end(), [key_bits](const Key_value<Value>& item) {
                      return item.key >> key_bits == 0;
                    }));
  if(key_bits == 0)
    return;
  scratch.resize(n);
  const int chunks = chunk_count(n, num_threads);
  if(n >= radix_detail::msd_min_items && key_bits > radix_detail::top_digit_bits) {
    radix_detail::sort_msd(items, scratch, key_bits, chunks);
    return;
  }
  const bool in_cache = 2 * n * sizeof(Key_value<Value>) <= radix_detail::in_cache_bytes;
  const int max_bits = chunks > 1 || in_cache ? radix_detail::wide_digit_bits : radix_detail::narrow_digit_bits;
  const radix_detail::Digit_plan plan = radix_detail::plan_digits(key_bits, max_bits);
  if(chunks > 1)
    radix_detail::sort_chunked(items, scratch, plan, chunks);
  else
    radix_detail::sort_sequential(items, scratch, plan);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_RADIX_SORT_H
