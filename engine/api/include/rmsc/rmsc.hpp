// rmsc public API, all of it: #include <rmsc/rmsc.hpp>. docs/embedding.md describes it.
#pragma once

#include "rmsc/context.hpp"
#include "rmsc/error.hpp"
#include "rmsc/image.hpp"
#include "rmsc/light.hpp"
#include "rmsc/mesh.hpp"
#include "rmsc/renderer.hpp"
#include "rmsc/scene.hpp"
#include "rmsc/scene_builder.hpp"
#include "rmsc/version.hpp"
