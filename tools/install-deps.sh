#!/usr/bin/env bash
# Installs everything rmsc needs to build, run and test, from Debian 12 packages only.
# Why each package is there: see "Dependencies" in README.md.
set -euo pipefail
packages=(
  cmake g++ make pkg-config python3   # build tools; python3 runs glad and the CLI tests
  python3-glad                        # generates the OpenGL 4.5 core loader at configure time
  libglm-dev                          # vector and matrix maths (C++ and GLSL-like)
  nlohmann-json3-dev                  # scene files (JSON)
  libtinygltf-dev                     # glTF 2.0 parsing
  libstb-dev                          # stb_image (textures, PNG reading) and stb_image_write (PNG)
  libpng-dev                          # 16-bit PNG output of the depth AOV
  libegl-dev libegl-mesa0             # headless GL through EGL's surfaceless platform
  libosmesa6-dev                      # headless GL through OSMesa
  libgl1-mesa-dri                     # Mesa's llvmpipe software rasterizer
  libglfw3-dev                        # windows and input for the viewer
  libimgui-dev                        # Dear ImGui (with GLFW and OpenGL 3 back ends) for the viewer's editor
  xvfb                                # a virtual X display for the viewer's end-to-end test
  libgtest-dev                        # unit and GPU tests
  clang libclang-rt-14-dev            # the sanitizer and fuzzer build (tools/sanitized-build.sh): clang, its runtimes
  python3-jsonschema                  # the CLI test checks the samples against docs/scene.schema.json
  pybind11-dev python3-dev            # the Python module (python/): bindings, Python's headers
  python3-numpy                       # the Python module's images are NumPy arrays
  python3-pytest                      # the Python module's tests
)
if [ "$(id -u)" -ne 0 ]; then sudo=sudo; else sudo=; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
