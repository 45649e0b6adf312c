// Large buffers filled front to back once (a fit's pieces, a program's blocks, a contour's moves).
#pragma once
#include <cstddef>
#include <vector>

namespace ncurve::base {

// Asks for 2 MB pages over the whole 2 MB pages of [data, data + bytes): one page fault for each
// instead of 512 (Linux transparent huge pages in madvise mode; elsewhere nothing). Buffers under
// 4 MB are left alone.
void advise_huge_pages(void* data, std::size_t bytes);

// v.reserve(n), its room advised as above.
template <class T>
void reserve_large(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace ncurve::base
