// The target that precompiles QtWidgets once for every test (tests/CMakeLists.txt): each test
// parsed it anew, and compiling the tests took half the build's time.
int main()
{
    return 0;
}
