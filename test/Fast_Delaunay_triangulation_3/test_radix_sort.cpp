// Radix sort (paper §2.3): std::stable_sort is the oracle, on every key width, size class and thread count.

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

using namespace CGAL::Fast_Delaunay_triangulation_3_internal;

namespace test_radix_sort {

using Item = Key_value<std::uint32_t>;

std::uint64_t low_bits_mask(int key_bits)
{
  return key_bits == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << key_bits) - 1;
}

// Values are the input positions, so any instability shows up as a value mismatch between equal keys.
std::vector<Item> random_items(std::size_t n, int key_bits, std::uint64_t distinct_keys, std::uint64_t seed)
{
  std::mt19937_64 random(seed);
  std::vector<std::uint64_t> pool(distinct_keys);
  for(std::uint64_t& key : pool)
    key = random() & low_bits_mask(key_bits);
  std::vector<Item> items(n);
  for(std::size_t i = 0; i < n; ++i)
    items[i] = {pool[random() % distinct_keys], std::uint32_t(i)};
  return items;
}

std::vector<Item> stable_sorted(std::vector<Item> items)
{
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.key < b.key; });
  return items;
}

::testing::AssertionResult same_items(const std::vector<Item>& expected, const std::vector<Item>& actual)
{
  if(expected.size() != actual.size())
    return ::testing::AssertionFailure() << "size " << actual.size() << " instead of " << expected.size();
  for(std::size_t i = 0; i < expected.size(); ++i)
    if(expected[i].key != actual[i].key || expected[i].value != actual[i].value)
      return ::testing::AssertionFailure() << "position " << i << ": (" << actual[i].key << ", " << actual[i].value
                                           << ") instead of (" << expected[i].key << ", " << expected[i].value << ")";
  return ::testing::AssertionSuccess();
}

const int key_widths[] = {1, 2, 3, 7, 8, 9, 11, 12, 21, 22, 23, 27, 30, 33, 34, 44, 45, 57, 63, 64};
const std::size_t sizes[] = {0, 1, 2, 63, 64, 65, 1000, 100000};

TEST(RadixSort, MatchesStableSortOnRandomKeys)
{
  for(int key_bits : key_widths)
    for(std::size_t n : sizes) {
      const std::vector<Item> input = random_items(n, key_bits, std::max<std::size_t>(n, 1), 100 + key_bits);
      const std::vector<Item> expected = stable_sorted(input);
      std::vector<Item> items = input, scratch;
      radix_sort(items, scratch, key_bits);
      ASSERT_TRUE(same_items(expected, items)) << "key_bits " << key_bits << ", n " << n;
    }
}

TEST(RadixSort, StableWithManyDuplicates)
{
  for(int key_bits : {4, 16, 40, 64})
    for(std::uint64_t distinct : {1u, 2u, 5u, 300u}) {
      const std::vector<Item> input = random_items(50000, key_bits, distinct, distinct * 1000 + key_bits);
      std::vector<Item> items = input, scratch;
      radix_sort(items, scratch, key_bits);
      ASSERT_TRUE(same_items(stable_sorted(input), items)) << "key_bits " << key_bits << ", distinct " << distinct;
    }
}

TEST(RadixSort, ThreadCountsGiveIdenticalResults)
{
  for(int key_bits : key_widths)
    for(std::size_t n : sizes) {
      const std::vector<Item> input = random_items(n, key_bits, std::max<std::size_t>(n / 3, 1), 7 * key_bits + n);
      const std::vector<Item> expected = stable_sorted(input);
      for(int threads : {1, 2, 3}) {
        std::vector<Item> items = input, scratch;
        radix_sort(items, scratch, key_bits, threads);
        ASSERT_TRUE(same_items(expected, items)) << "key_bits " << key_bits << ", n " << n << ", threads " << threads;
      }
    }
}

// Past the size where several chunks are used for real, with chunks of unequal sizes (n not a multiple of 3).
TEST(RadixSort, LargeInputAcrossChunks)
{
  const std::size_t n = 3 * min_items_per_chunk * 2 + 17;
  for(int key_bits : {10, 30, 64}) {
    const std::vector<Item> input = random_items(n, key_bits, n / 2, key_bits);
    const std::vector<Item> expected = stable_sorted(input);
    for(int threads : {1, 2, 3, 8}) {
      std::vector<Item> items = input, scratch;
      radix_sort(items, scratch, key_bits, threads);
      ASSERT_TRUE(same_items(expected, items)) << "key_bits " << key_bits << ", threads " << threads;
    }
  }
}

// A pass whose digit is the same for every item is skipped, which changes which buffer ends up holding the result.
TEST(RadixSort, SkippedPassesStillEndInItems)
{
  for(int used_bits : {5, 11, 12, 23, 40}) {
    const std::vector<Item> input = random_items(20000, used_bits, 20000, used_bits);
    std::vector<Item> items = input, scratch(5, Item{123, 456});
    radix_sort(items, scratch, 64, 2);
    ASSERT_TRUE(same_items(stable_sorted(input), items)) << "used_bits " << used_bits;
  }
}

TEST(RadixSort, ScratchOfAnySizeIsReused)
{
  const std::vector<Item> input = random_items(5000, 20, 5000, 3);
  const std::vector<Item> expected = stable_sorted(input);
  std::vector<Item> scratch(100000, Item{~std::uint64_t(0), 9});
  for(int round = 0; round < 3; ++round) {
    std::vector<Item> items = input;
    radix_sort(items, scratch, 20, round + 1);
    ASSERT_TRUE(same_items(expected, items)) << "round " << round;
  }
}

TEST(RadixSort, ZeroKeyBitsKeepsOrder)
{
  std::vector<Item> items(1000), scratch;
  for(std::size_t i = 0; i < items.size(); ++i)
    items[i] = {0, std::uint32_t(items.size() - i)};
  const std::vector<Item> input = items;
  radix_sort(items, scratch, 0, 2);
  EXPECT_TRUE(same_items(input, items));
}

TEST(RadixSort, OtherValueTypes)
{
  struct Payload
  {
    double x;
    std::uint16_t tag;
  };
  std::mt19937_64 random(11);
  std::vector<Key_value<Payload>> items(4000), scratch;
  for(std::size_t i = 0; i < items.size(); ++i)
    items[i] = {random() % 97, Payload{double(i), std::uint16_t(i)}};
  std::vector<Key_value<Payload>> expected = items;
  std::stable_sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
  radix_sort(items, scratch, 7);
  for(std::size_t i = 0; i < items.size(); ++i) {
    ASSERT_EQ(items[i].key, expected[i].key);
    ASSERT_EQ(items[i].value.x, expected[i].value.x);
    ASSERT_EQ(items[i].value.tag, expected[i].value.tag);
  }
}

// Large arrays are sorted top digit first, then bucket by bucket only as deep as the keys differ: clustered keys
// (long shared prefixes, one huge bucket, runs of equal keys, buckets just above and below the insertion-sort size)
// must still come out as the stable sort's, on any number of threads.
TEST(RadixSort, ClusteredKeysTopDigitFirst)
{
  std::mt19937_64 random(5);
  for(int key_bits : {12, 40, 63, 64}) {
    const std::uint64_t mask = low_bits_mask(key_bits);
    std::vector<Item> input(150001);
    for(std::size_t i = 0; i < input.size(); ++i) {
      std::uint64_t key;
      switch(i % 5) {
      case 0: key = random(); break;                                 // spread over every bucket
      case 1: key = 0x5a5a5a5a5a5a5a5aull ^ (random() & 0xfff); break; // one cluster sharing all but 12 bits
      case 2: key = 0x5a5a5a5a5a5a5a5aull ^ (random() & 0x3); break;   // runs of equal keys inside it
      case 3: key = (i / 97) << 20; break;                             // buckets of ~20 to ~100 items
      default: key = ~std::uint64_t(0) - (random() & 0xffff); break;    // the top bucket
      }
      input[i] = {key & mask, std::uint32_t(i)};
    }
    const std::vector<Item> expected = stable_sorted(input);
    for(int threads : {1, 2, 3}) {
      std::vector<Item> items = input, scratch;
      radix_sort(items, scratch, key_bits, threads);
      ASSERT_TRUE(same_items(expected, items)) << "key_bits " << key_bits << ", threads " << threads;
    }
    // Powers of two: every level splits off one key and sends the rest one digit deeper.
    std::vector<Item> powers(100003);
    for(std::size_t i = 0; i < powers.size(); ++i)
      powers[i] = {(std::uint64_t(1) << (i * 7 % 64)) & mask, std::uint32_t(i)};
    std::vector<Item> items = powers, scratch;
    radix_sort(items, scratch, key_bits, 2);
    ASSERT_TRUE(same_items(stable_sorted(powers), items)) << "powers of two, key_bits " << key_bits;
  }
}

} // namespace test_radix_sort
