// The gaphys GA runtime: what every generated algebra header includes.
#pragma once

#include "mv_algorithms.hpp"
#include "compiler.hpp"
#include "mv_dispatch.hpp"
#include "mv_functions.hpp"
#include "scalar_functions.hpp"
#include "sparse_mv.hpp"
#include "table_product.hpp"
#include "uninitialized.hpp"
#include "version.hpp"
