// toml++'s parser compiled into this library once (TOML_IMPLEMENTATION), instead of loading its
// shared library: the lean plastica then links the C++ runtime statically and starts without
// loading libstdc++ (cli/CMakeLists.txt).
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
