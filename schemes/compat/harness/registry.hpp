// Kept for plug-ins written before the registry moved to schemes/registry.hpp (rotbench
// 0.1): installed as <rotbench/harness/registry.hpp>. New code includes schemes/registry.hpp.
#pragma once

#include "schemes/registry.hpp"
