// The JSON Schema (draft 2020-12) of scene files. What each key's value looks like is written
// in scene_schema.cpp; which keys and names exist is checked against the reader itself: the
// generator feeds the reader a probe document for every kind of object and reads the known
// keys and names back from its unknown-key warnings and unknown-name errors. Primitive shapes
// come straight from the catalogue. docs/scene.schema.json is this generator's output
// (`rmsc schema > docs/scene.schema.json`); a unit test keeps the two identical.
#pragma once

#include <string>
#include <vector>

namespace rmsc {

struct SceneSchema {
    std::string text; // the schema, JSON indented by 2, ending in a newline
    // Keys or names the reader knows that scene_schema.cpp does not describe, and the reverse,
    // each saying what to add where. Empty when schema and reader agree.
    std::vector<std::string> problems;
};

SceneSchema generateSceneSchema();

} // namespace rmsc
