# warnings as errors for our own code only: an INTERFACE target linked PRIVATE
add_library(clothbench_warnings INTERFACE)
add_library(clothbench::warnings ALIAS clothbench_warnings)
target_compile_options(clothbench_warnings INTERFACE -Wall -Wextra -Wpedantic -Werror -Wno-missing-field-initializers)

# one set of flags for every module; recorded in every report
add_library(clothbench_flags INTERFACE)
add_library(clothbench::flags ALIAS clothbench_flags)
target_compile_features(clothbench_flags INTERFACE cxx_std_17)
# -fno-semantic-interposition: a shared library's own calls bind to its own functions (nobody interposes them), so
# the compiler may inline them within a file (the velocity limit's per-spring call: the same results, 8 % faster)
target_compile_options(clothbench_flags INTERFACE -fno-math-errno -fno-semantic-interposition)
if(CLOTHBENCH_SANITIZE)
  target_compile_options(clothbench_flags INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(clothbench_flags INTERFACE -fsanitize=address,undefined)
endif()
