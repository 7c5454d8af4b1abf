// Included before every source of the fuzz build (CMakeLists.txt, ANGIORAY_FUZZ). Debian's ITK 5.2
// headers were generated for GCC only: itk_compiler_detection.h stops with "Unsupported compiler"
// under clang. Read once here as GCC 12 (whose C++20 features clang 14 has too), its include guard
// keeps ITK's own includes of it from reading it again.
#if __has_include(<itk_compiler_detection.h>) && defined(__clang__)
#pragma push_macro("__clang__")
#pragma push_macro("__GNUC__")
#pragma push_macro("__GNUC_MINOR__")
#undef __clang__
#undef __GNUC__
#undef __GNUC_MINOR__
#define __GNUC__ 12
#define __GNUC_MINOR__ 2
#include <itk_compiler_detection.h>
#pragma pop_macro("__GNUC_MINOR__")
#pragma pop_macro("__GNUC__")
#pragma pop_macro("__clang__")
#endif
