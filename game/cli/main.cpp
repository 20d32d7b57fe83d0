// oceanbox entry point.
#include "cli/cli.h"

#include <cstdlib>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

int main(int argc, char** argv) {
#if defined(__GLIBC__)
    // The GL driver allocates and frees megabytes every frame (texture uploads, mipmaps): by
    // default glibc gives the top of the heap back to the kernel each time and faults it in
    // again, page by page (5 % of the main thread on llvmpipe). Grow it 64 MiB at a time and
    // keep up to 256 MiB of it.
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_TOP_PAD, 64 << 20);
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
#endif
    return ob::game::runCli(argc, argv);
}
