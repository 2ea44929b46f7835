#include "umockdev_harness.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>

namespace nb::test {

void reexecUnderUmockdev(int, char** argv)
{
    // umockdev_in_mock_environment() only turns true once a testbed exists, so mark the child.
    if (std::getenv("NB_UNDER_UMOCKDEV"))
        return;
    const char* preload = "libumockdev-preload.so.0";
    bool found = false;
    for (const char* dir : {"/usr/lib/x86_64-linux-gnu", "/usr/lib64", "/usr/lib", "/usr/local/lib"})
        found = found || access((std::string(dir) + "/" + preload).c_str(), R_OK) == 0;
    if (!found) {
        std::fprintf(stderr, "umockdev's %s is not installed: skipping\n", preload);
        std::exit(77);
    }
    std::string value = preload;
    if (const char* old = std::getenv("LD_PRELOAD"); old && *old)
        value = value + ":" + old;
    setenv("LD_PRELOAD", value.c_str(), 1);
    // A sanitizer build wants its runtime first in the library list; the preload is harmless.
    std::string asan = "verify_asan_link_order=0";
    if (const char* old = std::getenv("ASAN_OPTIONS"); old && *old)
        asan = std::string(old) + ":" + asan;
    setenv("ASAN_OPTIONS", asan.c_str(), 1);
    setenv("NB_UNDER_UMOCKDEV", "1", 1);
    execv("/proc/self/exe", argv);
    std::perror("re-executing under umockdev");
    std::exit(1);
}

}  // namespace nb::test
