// Typed reading of YAML values in a scene file: every wrong value becomes a located, worded problem.
#pragma once

#include "jl/scene/bound.h"
#include "jl/scene/scene.h"
#include "jl/scene/scene_fields.h"
#include "problems.h"

#include <yaml-cpp/node/node.h>

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace jl {

void report(Problems& problems, const YAML::Mark& mark, std::string message);

// A value with where it is and what it is called in messages
// ("ladder.block.mass"). A missing value is located at its key.
struct Located {
    YAML::Node node;
    YAML::Mark mark;
    std::string path;
};
Located locate(const YAML::Node& node, std::string path);

// Value readers: each reports and returns nullopt when the value is not what
// is expected.
std::optional<double> readNumber(Problems&, const Located&, Bound bound);
std::optional<long long> readInteger(Problems&, const Located&, long long lo, long long hi);
std::optional<double> readAngle(Problems&, const Located&, Bound bound);
std::optional<Point2> readPoint(Problems&, const Located&, Bound bound);  // each coordinate
std::optional<Color> readColor(Problems&, const Located&);
std::optional<bool> readFlag(Problems&, const Located&);
std::optional<std::string> readText(Problems&, const Located&);
// Reports and returns false when the value is not a list.
bool expectList(Problems&, const Located&);
void fail(Problems&, const Located&, const std::string& expected);  // "path: expected X, got Y"

// What the message of an unknown key adds beyond the closest known key:
// words that are no key's misspelling but mean one ("rotate" for "turn"),
// and what the keys of the mapping are, when no suggestion fits.
struct KeyHelp {
    std::vector<std::pair<std::string_view, std::string_view>> meanings;  // word -> key
    std::string_view keys;                                                // "an entry is 'at' and one action: ..."
};

// One YAML mapping being read. Unknown keys are reported on construction,
// with the closest known key as a suggestion.
class Fields {
public:
    Fields(Problems& problems, const Located& map, const std::vector<std::string_view>& known,
           const KeyHelp& help = {});

    bool isMap() const { return isMap_; }
    bool hadUnknownKeys() const { return unknownKeys_; }
    bool has(std::string_view key) const { return find(key) != nullptr; }
    Located value(std::string_view key) const;  // a null node at the mapping when absent
    const YAML::Mark& mark() const { return mark_; }
    const std::string& path() const { return path_; }
    std::string pathOf(std::string_view key) const;
    Problems& problems() const { return problems_; }
    // Reports a missing key at the mapping itself.
    bool require(std::string_view key);
    void errorAt(std::string_view key, const std::string& message) const;  // "path: message" at the value

    // Each leaves `out` untouched when the key is absent or wrong. Every
    // number has a range (jl/scene/scene_ranges.h): none is left unbounded.
    void number(std::string_view key, double& out, Bound bound);
    void number(std::string_view key, std::optional<double>& out, Bound bound);
    void integer(std::string_view key, int& out, long long lo, long long hi);
    void angle(std::string_view key, double& out, Bound bound);
    void angle(std::string_view key, std::optional<double>& out, Bound bound);
    void point(std::string_view key, Point2& out, Bound bound);
    void color(std::string_view key, Color& out);
    void color(std::string_view key, std::optional<Color>& out);
    void flag(std::string_view key, bool& out);
    // At most `mostCharacters` characters (UTF-8 code points).
    void text(std::string_view key, std::string& out, std::size_t mostCharacters);
    // A word from a fixed set (jl/scene/scene_fields.h), e.g. integrator: rk4.
    template <class E>
    void choice(std::string_view key, E& out, std::span<const Word<E>> words);
    // A number of the table (jl/scene/scene_fields.h) into its place in
    // `section`: its key, its range, and whether it is an angle or required.
    template <class Section>
    void read(const NumberField<Section>& n, Section& section);
    // Each number of a section's table, in the table's order.
    template <class Section, std::size_t N>
    void readAll(const NumberField<Section> (&numbers)[N], Section& section) {
        for (const NumberField<Section>& n : numbers) read(n, section);
    }

private:
    struct Entry {
        std::string key;
        Located value;
    };
    const Entry* find(std::string_view key) const;
    void chooseFrom(std::string_view key, const std::vector<std::string_view>& words, int& index);

    Problems& problems_;
    YAML::Mark mark_;
    std::string path_;
    bool isMap_ = false;
    bool unknownKeys_ = false;
    std::vector<Entry> entries_;
};

template <class E>
void Fields::choice(std::string_view key, E& out, std::span<const Word<E>> words) {
    std::vector<std::string_view> names;
    for (const Word<E>& w : words) names.push_back(w.word);
    int index = -1;
    chooseFrom(key, names, index);
    if (index >= 0) out = words[size_t(index)].value;
}

template <class Section>
void Fields::read(const NumberField<Section>& n, Section& section) {
    if (n.is(kRequired) && !require(n.key)) return;
    visitValue(n, section, [&](auto& value) {
        if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, Point2>)
            point(n.key, value, n.range);
        else if constexpr (std::is_same_v<std::remove_reference_t<decltype(value)>, double>)
            n.is(kAngle) ? angle(n.key, value, n.range) : number(n.key, value, n.range);
        else
            n.is(kAngle) ? angle(n.key, value, n.range) : number(n.key, value, n.range);
    });
}

// The known word closest to `word` if it is close enough to be a likely typo.
std::optional<std::string_view> closestWord(std::string_view word, const std::vector<std::string_view>& known);

}  // namespace jl
