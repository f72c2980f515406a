// The JSON the command line writes (run summaries, bench's last line; the
// events are jl/sim/event_json.h's), built with nlohmann-json, keys in the order they are given. JSON
// text is UTF-8: bytes of a string that are not (a file name in another
// encoding) are written as U+FFFD rather than break every reader; a number
// that is not finite is null, as JSON has no NaN or infinity.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace jl::cli {

using Json = nlohmann::ordered_json;

inline std::string jsonText(const Json& json) { return json.dump(-1, ' ', false, Json::error_handler_t::replace); }

}  // namespace jl::cli
