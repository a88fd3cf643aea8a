// libgaphys: everything an application needs.
#pragma once

#include "gaphys/algebra.hpp"
#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/conversions.hpp"
#include "gaphys/error.hpp"
#include "gaphys/inertia.hpp"
#include "gaphys/material.hpp"
#include "gaphys/shape.hpp"
#include "gaphys/space.hpp"
#include "gaphys/world.hpp"
