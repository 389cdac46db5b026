#include "engine/cpu_allocator.h"

#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cetview::engine {

void keepFreedMemoryForCpuRendering() {
#if defined(__GLIBC__)
  // Setting either also stops glibc from moving the thresholds itself.
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's maximum on 64-bit systems
#endif
}

}  // namespace cetview::engine
