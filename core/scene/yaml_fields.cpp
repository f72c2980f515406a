// Every message names the value by its path and says what was expected and
// what was found, in words a teacher can act on.
#include "yaml_fields.h"

#include "jl/scene/scalar_text.h"
#include "shown_text.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>

namespace jl {

void report(Problems& problems, const YAML::Mark& mark, std::string message) {
    problems.add(mark.line + 1, mark.column + 1, std::move(message));
}

Located locate(const YAML::Node& node, std::string path) { return {node, node.Mark(), std::move(path)}; }

namespace {

bool isQuoted(const YAML::Node& node) { return node.Tag() == "!"; }

// How a wrong value looks, for "expected X, got Y".
std::string describe(const YAML::Node& node) {
    if (!node.IsDefined() || node.IsNull()) return "nothing";
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a mapping";
    std::string text = node.Scalar();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return (isQuoted(node) ? "the quoted text '" : "'") + text + "'";
}

bool isNonFinite(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    if (!text.empty() && (text[0] == '+' || text[0] == '-')) text.erase(0, 1);
    return text == ".nan" || text == ".inf" || text == "nan" || text == "inf" || text == "infinity";
}

// The number in a plain scalar, with the reason when there is none.
std::optional<double> scalarNumber(Problems& problems, const Located& at, const std::string& expected, bool angle) {
    if (!at.node.IsScalar() || isQuoted(at.node)) {
        fail(problems, at, expected);
        return std::nullopt;
    }
    const std::string& text = at.node.Scalar();
    bool outOfRange = false;
    std::optional<double> value = angle ? parseAngle(text) : parseNumber(text, &outOfRange);
    if (value) return value;
    if (isNonFinite(text))
        report(problems, at.mark, at.path + ": expected a finite number, got '" + text + "'");
    else if (outOfRange)
        report(problems, at.mark, at.path + ": the number '" + text + "' is out of range");
    else
        fail(problems, at, expected);
    return std::nullopt;
}

std::optional<double> checked(Problems& problems, const Located& at, std::optional<double> value, Bound bound) {
    if (value && !bound.contains(*value)) {
        report(problems, at.mark, at.path + ": expected " + bound.describe() + ", got " + at.node.Scalar());
        return std::nullopt;
    }
    return value;
}

}  // namespace

void fail(Problems& problems, const Located& at, const std::string& expected) {
    report(problems, at.mark,
           (at.path.empty() ? "the scene" : at.path) + ": expected " + expected + ", got " + describe(at.node));
}

std::optional<double> readNumber(Problems& problems, const Located& at, Bound bound) {
    return checked(problems, at, scalarNumber(problems, at, bound.describe(), false), bound);
}

std::optional<double> readAngle(Problems& problems, const Located& at, Bound bound) {
    const std::string expected = "an angle (radians, or e.g. '180deg', '3.14rad')";
    return checked(problems, at, scalarNumber(problems, at, expected, true), bound);
}

std::optional<long long> readInteger(Problems& problems, const Located& at, long long lo, long long hi) {
    const std::string expected = hi == std::numeric_limits<long long>::max()
                                     ? "a whole number >= " + std::to_string(lo)
                                     : "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
    if (!at.node.IsScalar() || isQuoted(at.node)) {
        fail(problems, at, expected);
        return std::nullopt;
    }
    std::string_view text = at.node.Scalar();
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    long long value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range && end == text.data() + text.size()) {
        report(problems, at.mark, at.path + ": the number '" + std::string(text) + "' is out of range");
        return std::nullopt;
    }
    if (error != std::errc{} || end != text.data() + text.size() || value < lo || value > hi) {
        fail(problems, at, expected);
        return std::nullopt;
    }
    return value;
}

std::optional<Point2> readPoint(Problems& problems, const Located& at, Bound bound) {
    if (!at.node.IsSequence() || at.node.size() != 2) {
        fail(problems, at, "a point [x, y]");
        return std::nullopt;
    }
    const auto x = readNumber(problems, locate(at.node[0], at.path + "[0]"), bound);
    const auto y = readNumber(problems, locate(at.node[1], at.path + "[1]"), bound);
    if (!x || !y) return std::nullopt;
    return Point2{*x, *y};
}

std::optional<Color> readColor(Problems& problems, const Located& at) {
    const auto color = at.node.IsScalar() ? parseColor(at.node.Scalar()) : std::nullopt;
    if (!color) {
        // A bare #c8a26b is a YAML comment, so the value arrives empty.
        fail(problems, at, "a colour \"#rrggbb\" (in quotes: # starts a comment)");
    }
    return color;
}

std::optional<bool> readFlag(Problems& problems, const Located& at) {
    if (at.node.IsScalar() && !isQuoted(at.node)) {
        if (at.node.Scalar() == "true") return true;
        if (at.node.Scalar() == "false") return false;
    }
    fail(problems, at, "true or false");
    return std::nullopt;
}

std::optional<std::string> readText(Problems& problems, const Located& at) {
    if (at.node.IsScalar()) return at.node.Scalar();
    fail(problems, at, "text");
    return std::nullopt;
}

bool expectList(Problems& problems, const Located& at) {
    if (at.node.IsSequence()) return true;
    fail(problems, at, "a list");
    return false;
}

namespace {

std::string normalised(std::string_view word) {
    std::string out(word);
    for (char& c : out) c = c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = up;
        }
    }
    return row[b.size()];
}

}  // namespace

std::optional<std::string_view> closestWord(std::string_view word, const std::vector<std::string_view>& known) {
    if (word.size() > 64) return std::nullopt;  // not a typo; spare the quadratic work
    const std::string w = normalised(word);
    std::optional<std::string_view> best;
    std::size_t bestDistance = std::max<std::size_t>(2, w.size() / 3) + 1;
    for (std::string_view k : known) {
        const std::size_t d = editDistance(w, normalised(k));
        if (d < bestDistance && d < w.size()) best = k, bestDistance = d;
    }
    return best;
}

namespace {

// The known key that `word` most likely stands for, if any: a misspelling
// first, then a word of the same meaning.
std::optional<std::string_view> meantKey(std::string_view word, const std::vector<std::string_view>& known,
                                         const KeyHelp& help) {
    if (const auto guess = closestWord(word, known)) return guess;
    const std::string w = normalised(word);
    for (const auto& [other, key] : help.meanings)
        if (normalised(other) == w) return key;
    return std::nullopt;
}

}  // namespace

Fields::Fields(Problems& problems, const Located& map, const std::vector<std::string_view>& known, const KeyHelp& help)
    : problems_(problems), mark_(map.mark), path_(map.path), isMap_(map.node.IsMap()) {
    if (!isMap_) {
        fail(problems, map, "a mapping of keys (key: value)");
        return;
    }
    const std::vector<std::string_view>& words = known;
    for (auto it = map.node.begin(); it != map.node.end(); ++it) {
        const YAML::Node key = it->first, value = it->second;
        if (!key.IsScalar()) {
            report(problems, key.Mark(), "a key must be a name, not " + describe(key));
            continue;
        }
        const std::string& name = key.Scalar();
        if (std::find(words.begin(), words.end(), name) == words.end()) {
            std::string message = "unknown key '" + shownText(name) + "'" + (path_.empty() ? "" : " in " + path_);
            if (const auto guess = meantKey(name, words, help))
                message += "; did you mean '" + std::string(*guess) + "'?";
            else if (!help.keys.empty())
                message += "; " + std::string(help.keys);
            report(problems, key.Mark(), std::move(message));
            unknownKeys_ = true;
            continue;
        }
        if (find(name)) continue;  // a duplicate, already reported by the first pass
        // A key with no value ("mass:") has its null node on the next line;
        // point at the key instead.
        entries_.push_back({name, {value, value.IsNull() ? key.Mark() : value.Mark(), pathOf(name)}});
    }
}

const Fields::Entry* Fields::find(std::string_view key) const {
    for (const Entry& e : entries_)
        if (e.key == key) return &e;
    return nullptr;
}

Located Fields::value(std::string_view key) const {
    if (const Entry* e = find(key)) return e->value;
    return {YAML::Node(), mark_, pathOf(key)};
}

std::string Fields::pathOf(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

bool Fields::require(std::string_view key) {
    if (!isMap_ || has(key)) return isMap_;
    report(problems_, mark_, "missing required key '" + pathOf(key) + "'");
    return false;
}

void Fields::errorAt(std::string_view key, const std::string& message) const {
    const Located at = value(key);
    report(problems_, at.mark, at.path + ": " + message);
}

void Fields::number(std::string_view key, double& out, Bound bound) {
    if (has(key))
        if (const auto v = readNumber(problems_, value(key), bound)) out = *v;
}

void Fields::number(std::string_view key, std::optional<double>& out, Bound bound) {
    if (has(key))
        if (const auto v = readNumber(problems_, value(key), bound)) out = *v;
}

void Fields::integer(std::string_view key, int& out, long long lo, long long hi) {
    if (has(key))
        if (const auto v = readInteger(problems_, value(key), lo, hi)) out = static_cast<int>(*v);
}

void Fields::angle(std::string_view key, double& out, Bound bound) {
    if (has(key))
        if (const auto v = readAngle(problems_, value(key), bound)) out = *v;
}

void Fields::angle(std::string_view key, std::optional<double>& out, Bound bound) {
    if (has(key))
        if (const auto v = readAngle(problems_, value(key), bound)) out = *v;
}

void Fields::point(std::string_view key, Point2& out, Bound bound) {
    if (has(key))
        if (const auto v = readPoint(problems_, value(key), bound)) out = *v;
}

void Fields::color(std::string_view key, Color& out) {
    if (has(key))
        if (const auto v = readColor(problems_, value(key))) out = *v;
}

void Fields::color(std::string_view key, std::optional<Color>& out) {
    if (has(key))
        if (const auto v = readColor(problems_, value(key))) out = *v;
}

void Fields::flag(std::string_view key, bool& out) {
    if (has(key))
        if (const auto v = readFlag(problems_, value(key))) out = *v;
}

void Fields::text(std::string_view key, std::string& out, std::size_t mostCharacters) {
    if (!has(key)) return;
    const Located at = value(key);
    const auto v = readText(problems_, at);
    if (!v) return;
    // Every byte but a UTF-8 continuation byte (10xxxxxx) starts a character.
    const auto characters = std::size_t(
        std::count_if(v->begin(), v->end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
    if (characters > mostCharacters) {
        report(
            problems_, at.mark,
            at.path + ": at most " + std::to_string(mostCharacters) + " characters, got " + std::to_string(characters));
        return;
    }
    out = *v;
}

void Fields::chooseFrom(std::string_view key, const std::vector<std::string_view>& words, int& index) {
    if (!has(key)) return;
    const Located at = value(key);
    if (at.node.IsScalar()) {
        const auto it = std::find(words.begin(), words.end(), at.node.Scalar());
        if (it != words.end()) {
            index = static_cast<int>(it - words.begin());
            return;
        }
    }
    std::string expected = "one of";
    for (std::size_t i = 0; i < words.size(); ++i) expected += (i ? ", " : " ") + std::string(words[i]);
    if (at.node.IsScalar())
        if (const auto guess = closestWord(at.node.Scalar(), words))
            expected += " (did you mean '" + std::string(*guess) + "'?)";
    fail(problems_, at, expected);
}

}  // namespace jl
