// The symbol that says which scalar this engine library was built with
// (gaphys/algebra.hpp): a program compiled with the other one refers to a
// symbol no library defines, and fails to link instead of running on structs
// of another layout.
#include "gaphys/algebra.hpp"

namespace gaphys::detail {

extern const int GAPHYS_DETAIL_SCALAR_CHECK = 1;

}  // namespace gaphys::detail
