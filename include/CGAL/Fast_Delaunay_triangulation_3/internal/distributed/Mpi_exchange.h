// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The few collective operations the distributed triangulation is made of, typed: an all-to-all of per-rank
// vectors of fixed-size records, an all-gather of one vector per rank, sums and extremes over ranks. Records travel
// as bytes of a contiguous MPI type, so any trivially copyable struct can be sent; counts are in records, and a
// rank's total must fit MPI's int (2^31 records: 64 GiB of 32-byte records, far past one rank's memory).
// Every function here is collective: all ranks of the communicator call it in the same order.

#ifndef CGAL_FDT3_INTERNAL_DISTRIBUTED_MPI_EXCHANGE_H
#define CGAL_FDT3_INTERNAL_DISTRIBUTED_MPI_EXCHANGE_H

#include <mpi.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace distributed {

// An MPI type of sizeof(Record) bytes, freed with the object.
template <class Record>
class Record_type
{
  static_assert(std::is_trivially_copyable<Record>::value, "records are sent as bytes");

public:
  Record_type()
  {
    MPI_Type_contiguous(int(sizeof(Record)), MPI_BYTE, &type_);
    MPI_Type_commit(&type_);
  }
  ~Record_type() { MPI_Type_free(&type_); }
  Record_type(const Record_type&) = delete;
  Record_type& operator=(const Record_type&) = delete;
  MPI_Datatype get() const { return type_; }

private:
  MPI_Datatype type_;
};

inline int checked_count(std::size_t n, const char* what)
{
  if(n > std::size_t(std::numeric_limits<int>::max()))
    throw std::length_error(std::string("distributed Delaunay: ") + what + " exceeds 2^31 records on one rank");
  return int(n);
}

class Communicator
{
public:
  explicit Communicator(MPI_Comm comm) : comm_(comm)
  {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
  }

  MPI_Comm get() const { return comm_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

  // outgoing[r] goes to rank r; returns the records received, grouped by source rank in rank order, and, if
  // `from` is given, for each source rank where its records start (size() + 1 entries).
  template <class Record>
  std::vector<Record> all_to_all(const std::vector<std::vector<Record>>& outgoing,
                                 std::vector<std::size_t>* from = nullptr, std::uint64_t* bytes_sent = nullptr) const
  {
    const Record_type<Record> type;
    std::vector<int> send_counts(size_), send_offsets(size_), receive_counts(size_), receive_offsets(size_);
    std::size_t total = 0;
    for(int r = 0; r < size_; ++r) {
      send_counts[r] = checked_count(outgoing[r].size(), "a message");
      send_offsets[r] = checked_count(total, "the records sent");
      total += outgoing[r].size();
    }
    checked_count(total, "the records sent");
    std::vector<Record> packed;
    packed.reserve(total);
    for(int r = 0; r < size_; ++r) packed.insert(packed.end(), outgoing[r].begin(), outgoing[r].end());
    if(bytes_sent) {
      for(int r = 0; r < size_; ++r)
        if(r != rank_) *bytes_sent += sizeof(Record) * outgoing[r].size();
    }
    MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm_);
    std::size_t received = 0;
    for(int r = 0; r < size_; ++r) {
      receive_offsets[r] = checked_count(received, "the records received");
      received += std::size_t(receive_counts[r]);
    }
    checked_count(received, "the records received");
    std::vector<Record> incoming(received);
    MPI_Alltoallv(packed.data(), send_counts.data(), send_offsets.data(), type.get(), incoming.data(),
                  receive_counts.data(), receive_offsets.data(), type.get(), comm_);
    if(from) {
      from->assign(std::size_t(size_) + 1, 0);
      for(int r = 0; r < size_; ++r) (*from)[r + 1] = (*from)[r] + std::size_t(receive_counts[r]);
    }
    return incoming;
  }

  // Every rank's `mine`, concatenated in rank order, on every rank (with where each rank's part starts).
  template <class Record>
  std::vector<Record> all_gather(const std::vector<Record>& mine, std::vector<std::size_t>* from = nullptr,
                                 std::uint64_t* bytes_sent = nullptr) const
  {
    const Record_type<Record> type;
    const int count = checked_count(mine.size(), "a gathered message");
    std::vector<int> counts(size_), offsets(size_);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
    std::size_t total = 0;
    for(int r = 0; r < size_; ++r) {
      offsets[r] = checked_count(total, "the records gathered");
      total += std::size_t(counts[r]);
    }
    checked_count(total, "the records gathered");
    if(bytes_sent) *bytes_sent += sizeof(Record) * mine.size() * std::uint64_t(size_ - 1);
    std::vector<Record> all(total);
    MPI_Allgatherv(mine.data(), count, type.get(), all.data(), counts.data(), offsets.data(), type.get(), comm_);
    if(from) {
      from->assign(std::size_t(size_) + 1, 0);
      for(int r = 0; r < size_; ++r) (*from)[r + 1] = (*from)[r] + std::size_t(counts[r]);
    }
    return all;
  }

  std::uint64_t sum(std::uint64_t x) const
  {
    std::uint64_t s = 0;
    MPI_Allreduce(&x, &s, 1, MPI_UINT64_T, MPI_SUM, comm_);
    return s;
  }
  std::uint64_t max(std::uint64_t x) const
  {
    std::uint64_t m = 0;
    MPI_Allreduce(&x, &m, 1, MPI_UINT64_T, MPI_MAX, comm_);
    return m;
  }
  std::uint64_t min(std::uint64_t x) const
  {
    std::uint64_t m = 0;
    MPI_Allreduce(&x, &m, 1, MPI_UINT64_T, MPI_MIN, comm_);
    return m;
  }
  double max(double x) const
  {
    double m = 0;
    MPI_Allreduce(&x, &m, 1, MPI_DOUBLE, MPI_MAX, comm_);
    return m;
  }
  // Element-wise minimum of n doubles, in place.
  void min_in_place(double* x, int n) const { MPI_Allreduce(MPI_IN_PLACE, x, n, MPI_DOUBLE, MPI_MIN, comm_); }
  // The sum of x over the ranks before this one.
  std::uint64_t exclusive_prefix_sum(std::uint64_t x) const
  {
    std::uint64_t before = 0;
    MPI_Exscan(&x, &before, 1, MPI_UINT64_T, MPI_SUM, comm_);
    return rank_ == 0 ? 0 : before;
  }
  // A string of rank `root`, on every rank.
  std::string broadcast(std::string s, int root) const
  {
    std::uint64_t n = s.size();
    MPI_Bcast(&n, 1, MPI_UINT64_T, root, comm_);
    s.resize(std::size_t(n));
    MPI_Bcast(&s[0], checked_count(std::size_t(n), "a message"), MPI_CHAR, root, comm_);
    return s;
  }

  // The complaint of the lowest rank that has one (an empty string: none), on every rank: so that bad input is
  // reported with the same words everywhere and every rank leaves the same collective step.
  std::string lowest_rank_complaint(const std::string& complaint) const
  {
    const std::uint64_t lowest = min(complaint.empty() ? std::uint64_t(size_) : std::uint64_t(rank_));
    return lowest == std::uint64_t(size_) ? std::string() : broadcast(complaint, int(lowest));
  }

private:
  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

} // namespace distributed
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DISTRIBUTED_MPI_EXCHANGE_H
