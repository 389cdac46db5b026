// The process's allocator, tuned for a CPU Vulkan device (lavapipe) rendering in this process.
//
// llvmpipe bins every frame into scenes built from 64 KB malloc blocks on lavapipe's queue thread
// and frees them once the scene is rasterised. glibc gives a thread arena's free top back to the
// kernel (madvise) whenever it exceeds the trim threshold, so on some runs every frame faulted
// tens of megabytes of fresh zeroed pages in again: a third of the front end's time, 1M-triangle
// frames at 60-70 ms instead of about 50. Keeping freed memory (up to the trim threshold) and
// serving allocations up to 32 MiB from the heap rather than fresh mappings ends that; the cost
// is that the process keeps its peak heap instead of returning it. No-op without glibc.
#pragma once

namespace cetview::engine {

// Called by createDevice() when it picks a CPU device; idempotent.
void keepFreedMemoryForCpuRendering();

}  // namespace cetview::engine
