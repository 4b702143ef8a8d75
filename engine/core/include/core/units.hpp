// The units of the numbers a scene holds (metres, degrees, ratios, counts...): a catalogue row
// names the unit of each of its numbers, so the docs tables, the inspector's tooltips and its
// clamping notices all say it from the same place.
#pragma once

#include <string_view>

namespace rmsc {

enum class Unit {
    None,            // a plain number (an exponent, a fractal's constant, a direction's component)
    Metres,          // a length in world units
    Degrees,         // an angle
    DegreesPerMetre, // a twist or bend: degrees of turn per metre along an axis
    PerMetre,        // a frequency or a change per metre
    Ratio,           // a factor or a fraction (1 = unchanged, or 0..1)
    Count,           // a whole number of things (copies, steps, samples, iterations)
    Pixels,          // image pixels
    Seconds,
    Milliseconds,
    MetresPerSecond,
    Candela, // a point or spot light's intensity, as glTF's KHR_lights_punctual
    Lux,     // a directional light's intensity, as glTF's KHR_lights_punctual
};

// Short form after a number: "m", "°", "°/m", "1/m", "s", "ms", "m/s", "px", "cd", "lx"; "" for
// None, Ratio and Count.
std::string_view unitSymbol(Unit unit);
// How the docs and tooltips say it after a range: "in metres", "in degrees", "per metre", "a
// ratio", "a count", "in pixels"...; "" for None.
std::string_view unitPhrase(Unit unit);
// Words: "metres", "degrees", "degrees per metre", "per metre", "ratio", "count", "pixels",
// "seconds", "milliseconds", "metres per second", "candela", "lux"; "" for None.
std::string_view unitName(Unit unit);

} // namespace rmsc
