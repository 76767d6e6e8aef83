#include "landscape_common.hpp"
namespace edgeland::bench { void register_crossover_benchmarks() {} }
