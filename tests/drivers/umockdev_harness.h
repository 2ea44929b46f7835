#pragma once
// Runs a test program under libumockdev-preload: the first call re-executes the program with
// the preload library (so libusb and sysfs look at the testbed); inside, it returns normally.
// Exits 77 (ctest: skipped) when umockdev is not installed.

namespace nb::test {

// Call first in main(). Returns only inside the mocked environment.
void reexecUnderUmockdev(int argc, char** argv);

}  // namespace nb::test
