// The first pass over a scene file: everything that must be refused before a
// YAML tree exists (a tree of an absurd or hostile file costs gigabytes).
#include "core/yaml_prepass.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace jl {

namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is invalid
// (overlong forms, surrogates and code points past U+10FFFF included).
std::size_t utf8Length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) return 1;
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if ((b0 & 0xE0) == 0xC0) n = 2, cp = b0 & 0x1F;
    else if ((b0 & 0xF0) == 0xE0) n = 3, cp = b0 & 0x0F;
    else if ((b0 & 0xF8) == 0xF0) n = 4, cp = b0 & 0x07;
    else return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < smallest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

}  // namespace

bool checkText(std::string_view text, Problems& problems) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8Length(text, i);
        if (n == 0) {
            char hex[8];
            std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned char>(text[i]));
            problems.add(line, column, std::string("the file is not UTF-8 text (byte ") + hex +
                                           " is not valid UTF-8); save it as UTF-8");
            return false;
        }
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (n == 1 && ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F)) {
            problems.add(line, column, "control character " + std::to_string(c) + " is not allowed in a YAML file");
            return false;
        }
        if (c == '\n') ++line, column = 1;
        else ++column;
        i += n;
    }
    return true;
}

namespace {

int oneBased(int zeroBased) { return zeroBased + 1; }

// Walks parse events keeping, per open mapping, the keys seen so far.
class StructureCheck : public YAML::EventHandler {
public:
    StructureCheck(std::size_t maxNodes, Problems& problems) : maxNodes_(maxNodes), problems_(problems) {}

    bool refused() const { return refused_; }

    const YAML::Mark& documentStart() const { return documentStart_; }

    void OnDocumentStart(const YAML::Mark& mark) override { documentStart_ = mark; }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark, std::string()); }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
        // An alias can repeat a large subtree many times over (the "billion
        // laughs"); scenes have no need for them.
        refuse(mark, "aliases ('*name') are not supported in scene files; write the value out");
        node(mark, std::nullopt);
    }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string& value) override {
        node(mark, value);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {
        node(mark, std::nullopt);
        open_.push_back({false, true, {}});
    }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
        node(mark, std::nullopt);
        open_.push_back({true, true, {}});
    }
    void OnSequenceEnd() override { close(); }
    void OnMapEnd() override { close(); }

    void refuse(const YAML::Mark& mark, std::string message) {
        if (!refused_ || problems_.size() < 50) problems_.add(oneBased(mark.line), oneBased(mark.column), std::move(message));
        refused_ = true;
    }

private:
    struct Level {
        bool isMap;
        bool atKey;
        std::unordered_map<std::string, YAML::Mark> keys;
    };

    // `scalar` is the text when the node is a scalar (a possible map key).
    void node(const YAML::Mark& mark, const std::optional<std::string>& scalar) {
        if (++count_ == maxNodes_ + 1)
            refuse(mark, "the file has more than " + std::to_string(maxNodes_) + " YAML values; refusing to read it");
        if (open_.empty() || !open_.back().isMap) return;
        Level& level = open_.back();
        if (level.atKey && scalar) checkKey(level, mark, *scalar);
        level.atKey = !level.atKey;
    }

    void checkKey(Level& level, const YAML::Mark& mark, const std::string& key) {
        const auto [it, inserted] = level.keys.emplace(key, mark);
        if (inserted) return;
        problems_.add(oneBased(mark.line), oneBased(mark.column),
                      "duplicate key '" + key + "' (first given at line " + std::to_string(oneBased(it->second.line)) +
                          ", column " + std::to_string(oneBased(it->second.column)) + ")");
    }

    void close() {
        if (!open_.empty()) open_.pop_back();
    }

    std::size_t maxNodes_;
    std::size_t count_ = 0;
    YAML::Mark documentStart_;
    bool refused_ = false;
    Problems& problems_;
    std::vector<Level> open_;
};

}  // namespace

bool checkStructure(std::string_view text, std::size_t maxNodes, Problems& problems) {
    std::istringstream stream{std::string(text)};
    StructureCheck check(maxNodes, problems);
    try {
        YAML::Parser parser(stream);
        int documents = 0;
        while (parser.HandleNextDocument(check)) {
            if (++documents > 1) {
                const YAML::Mark& mark = check.documentStart();
                problems.add(oneBased(mark.line), oneBased(mark.column), "the file holds more than one YAML document ('---'); a scene is one document");
                return false;
            }
        }
        if (documents == 0) {
            problems.add(1, 1, "the file holds no YAML document; a scene starts with 'format: jacobs-ladder/1'");
            return false;
        }
    } catch (const YAML::Exception& e) {
        // yaml-cpp's words for a tab in the indentation do not say "tab".
        const bool tabIndent = text.starts_with('\t') || text.find("\n\t") != std::string_view::npos;
        problems.add(oneBased(e.mark.line), oneBased(e.mark.column),
                     "malformed YAML: " + e.msg + (tabIndent ? " (tabs cannot indent YAML; use spaces)" : ""));
        return false;
    }
    return !check.refused();
}

}  // namespace jl
