// gaphys GA runtime version. Generated headers check it at compile time, so a
// header generated for another runtime fails loudly instead of misbehaving.
#pragma once

#define GAPHYS_GA_RUNTIME_VERSION 2
