// SPDX-License-Identifier: MIT
// Large buffers filled once (a million-span cache, a file read whole, a solver's arrays): on Linux with
// transparent huge pages in "madvise" mode, asking for them before the first write replaces one page fault
// per 4 KiB by one per 2 MiB (the faults were a quarter of `hula info` of a 10^6-pole curve). A hint only:
// the bytes, and so every result, are the same with or without it.
#pragma once

#include <cstddef>
#include <iterator>
#include <vector>

namespace hula {

/// Asks the kernel to back the whole 2 MiB pages inside [p, p + bytes) with huge pages; does nothing
/// below a few MiB, off Linux, or where the kernel refuses. Call it before the memory is first written.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;

/// `v` resized to `n` value-initialised elements, its storage advised as above first when it grows.
template <class T>
void resize_advised(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) {
    std::vector<T> fresh;
    fresh.reserve(n);
    advise_huge_pages(fresh.data(), n * sizeof(T));
    fresh.assign(std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
    v.swap(fresh);
  }
  v.resize(n);
}

}  // namespace hula
