#include "engine/memory_reuse.h"

// Any C library header defines __GLIBC__ (through <features.h>); without one before the test
// below, the function compiled to nothing unless a unity build happened to put another file's
// includes in front of it.
#include <cstdlib>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cam {

void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // glibc's largest allowed on 64-bit systems
    mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
}

}  // namespace cam
