// The first pass over a scene file: everything that must be refused before a
// YAML tree exists (a tree of an absurd or hostile file costs gigabytes).
#include "yaml_prepass.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/parser.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
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
    if ((b0 & 0xE0) == 0xC0)
        n = 2, cp = b0 & 0x1F;
    else if ((b0 & 0xF0) == 0xE0)
        n = 3, cp = b0 & 0x0F;
    else if ((b0 & 0xF8) == 0xF0)
        n = 4, cp = b0 & 0x07;
    else
        return 0;
    if (i + n > text.size()) return 0;
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < smallest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return n;
}

// Where `text` first holds what a scene file may not: a byte that is not
// UTF-8, or a control character other than tab, CR and LF. The C1 controls
// (U+0080 to U+009F) are controls as much as the C0 ones: no text a scene
// holds needs them, and they show as nothing or as garbage.
struct TextFault {
    std::size_t offset;
    bool notUtf8;            // else a control character
    std::uint32_t code = 0;  // the control character
};

// "1" for U+0001 (as the messages always said), "U+0085" for a C1 control.
std::string controlName(std::uint32_t code) {
    if (code < 0x80) return std::to_string(code);
    char name[16];
    std::snprintf(name, sizeof name, "U+%04X", static_cast<unsigned>(code));
    return name;
}

std::optional<TextFault> firstTextFault(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8Length(text, i);
        if (n == 0) return TextFault{i, true};
        const unsigned char c = static_cast<unsigned char>(text[i]);
        if (n == 1 && ((c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7F)) return TextFault{i, false, c};
        const unsigned char next = n == 2 ? static_cast<unsigned char>(text[i + 1]) : 0;
        if (n == 2 && c == 0xC2 && next < 0xA0) return TextFault{i, false, 0x80u + (next - 0x80u)};
        i += n;
    }
    return std::nullopt;
}

// Line and column (1-based, a column per character) of `offset`.
std::pair<int, int> position(std::string_view text, std::size_t offset) {
    int line = 1, column = 1;
    for (std::size_t i = 0; i < offset;) {
        if (text[i] == '\n')
            ++line, column = 1;
        else
            ++column;
        i += std::max<std::size_t>(1, utf8Length(text, i));
    }
    return {line, column};
}

// Where a plain key longer than YAML's limit of 1024 characters starts,
// and its length: yaml-cpp says only "illegal map value" of it.
std::optional<std::pair<std::size_t, std::size_t>> overlongKey(std::string_view text) {
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = text.substr(start, end - start);
        const std::size_t first = line.find_first_not_of(" -");
        const std::size_t colon = line.find(':');
        if (first != std::string_view::npos && colon != std::string_view::npos && colon > first && line[first] != '#' &&
            colon - first > 1024)
            return std::pair{start + first, colon - first};
        start = end + 1;
    }
    return std::nullopt;
}

}  // namespace

bool checkText(std::string_view text, const LoadLimits& limits, Problems& problems) {
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        if (end - start > limits.maxLineBytes) {
            const auto [line, column] = position(text, start);
            problems.add(
                line, column,
                "this line is " + std::to_string((end - start) >> 10) + " KiB long, more than the " +
                    std::to_string(limits.maxLineBytes >> 10) +
                    " KiB a scene file's line may have; a scene's longest value, its description, is at most " +
                    std::to_string(kMostDescriptionCharacters) + " characters");
            return false;
        }
        start = end + 1;
    }
    if (const auto fault = firstTextFault(text)) {
        const auto [line, column] = position(text, fault->offset);
        const unsigned char c = static_cast<unsigned char>(text[fault->offset]);
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        problems.add(
            line, column,
            fault->notUtf8
                ? std::string("the file is not UTF-8 text (byte ") + hex + " is not valid UTF-8); save it as UTF-8"
                : "control character " + controlName(fault->code) + " is not allowed in a YAML file");
        return false;
    }
    // A byte-order mark may open the file; anywhere else (a file saved with
    // one twice, or pasted together) it is invisible text that breaks a key.
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (const std::size_t bom = text.find(kByteOrderMark, text.starts_with(kByteOrderMark) ? 3 : 0);
        bom != std::string_view::npos) {
        const auto [line, column] = position(text, bom);
        problems.add(line, column,
                     "a byte-order mark (U+FEFF, invisible) stands here; only the file's first character may be one: "
                     "delete it");
        return false;
    }
    // The YAML reader takes only LF and CRLF as line breaks: a file with old
    // Mac line endings would read as one long line and fail far from here.
    for (std::size_t cr = text.find('\r'); cr != std::string_view::npos; cr = text.find('\r', cr + 1)) {
        if (cr + 1 < text.size() && text[cr + 1] == '\n') continue;
        const auto [line, column] = position(text, cr);
        problems.add(line, column,
                     "a line ends in a carriage return (CR) alone, which YAML readers do not take as a line break; "
                     "save the file with LF or CRLF line endings");
        return false;
    }
    return true;
}

namespace {

int oneBased(int zeroBased) { return zeroBased + 1; }

// Thrown from the event handler to stop the parse at once: past this
// nesting the parser's recursion, not the file, would give the message.
struct Abandoned {};

// A scene nests six levels deep at most (drags, an item, its samples, one
// sample); far more is a hostile or broken file.
constexpr std::size_t kDeepest = 32;

// The tag as written: yaml-cpp hands "!!str" on as its full name.
std::string writtenTag(const std::string& tag) {
    const std::string core = "tag:yaml.org,2002:";
    return tag.starts_with(core) ? "!!" + tag.substr(core.size()) : tag;
}

// Whether the quoted value whose opening quote is at `offset` is closed
// before the file ends. The YAML reader ends such a value at the end of the
// file without a word when a line break comes last, and the rest of the
// file vanishes into it. True when `offset` holds no quote (nothing to tell).
bool quoteClosed(std::string_view text, std::size_t offset) {
    if (offset >= text.size() || (text[offset] != '\'' && text[offset] != '"')) return true;
    const char quote = text[offset];
    for (std::size_t i = offset + 1; i < text.size(); ++i) {
        if (quote == '"' && text[i] == '\\') {
            ++i;  // an escape: the next character is not the end
        } else if (text[i] == quote) {
            if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
                ++i;  // '' is a quote inside single quotes
                continue;
            }
            return true;
        }
    }
    return false;
}

// Walks parse events keeping, per open mapping, the keys seen so far.
class StructureCheck : public YAML::EventHandler {
public:
    StructureCheck(std::string_view text, const LoadLimits& limits, Problems& problems)
        : text_(text), maxNodes_(limits.maxNodes), maxScalar_(limits.maxScalarBytes), problems_(problems) {}

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
    void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t, const std::string& value) override {
        checkTag(mark, tag);
        if (tag == "!" && mark.pos >= 0 && !quoteClosed(text_, static_cast<std::size_t>(mark.pos))) {
            refuse(mark, std::string("this quoted value is never closed: the file ends before its closing ") +
                             text_[static_cast<std::size_t>(mark.pos)]);
            throw Abandoned{};
        }
        if (value.size() > maxScalar_)
            refuse(mark, "this value is " + std::to_string(value.size() >> 10) + " KiB long, more than the " +
                             std::to_string(maxScalar_ >> 10) + " KiB a scene file's value may have");
        else
            checkEscapes(mark, value);
        node(mark, value);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {
        checkTag(mark, tag);
        node(mark, std::nullopt);
        open(mark, false);
    }
    void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {
        checkTag(mark, tag);
        node(mark, std::nullopt);
        open(mark, true);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapEnd() override { close(); }

    void refuse(const YAML::Mark& mark, std::string message) {
        if (!refused_ || problems_.size() < 50)
            problems_.add(oneBased(mark.line), oneBased(mark.column), std::move(message));
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

    void open(const YAML::Mark& mark, bool isMap) {
        if (open_.size() == kDeepest) {
            refuse(mark, "the values nest more than " + std::to_string(kDeepest) +
                             " levels deep here; a scene nests at most 6");
            throw Abandoned{};
        }
        open_.push_back({isMap, true, {}});
    }

    void close() {
        if (!open_.empty()) open_.pop_back();
    }

    // "?" is a plain value and "!" a quoted one: anything else was tagged.
    // A tag would make "!!str 6" text where the reader sees a number, and
    // the scene writer never writes one.
    void checkTag(const YAML::Mark& mark, const std::string& tag) {
        if (tag == "?" || tag == "!" || tag.empty()) return;
        refuse(mark, "tags ('" + writtenTag(tag) +
                         "') are not used in scene files; write a number or a word plainly, and text in quotes");
    }

    // An escape in quotes ("\x01", "\ud800") can make what the file's text
    // may not hold; the value must meet the same rule as the file.
    void checkEscapes(const YAML::Mark& mark, const std::string& value) {
        const auto fault = firstTextFault(value);
        if (!fault) return;
        // yaml-cpp gives the escape \N (NEL, U+0085) as the lone byte 0x85:
        // a C1 control, refused as such, not as text that is not UTF-8.
        if (fault->notUtf8 && value[fault->offset] == '\x85') {
            refuse(mark,
                   "control character U+0085 (next line, written as the escape \\N) is not allowed in a scene "
                   "file");
            return;
        }
        refuse(mark, fault->notUtf8 ? std::string("an escape here gives text that is not UTF-8")
                                    : "control character " + controlName(fault->code) +
                                          " (written as an escape) is not allowed in a scene file");
    }

    std::string_view text_;
    std::size_t maxNodes_, maxScalar_;
    std::size_t count_ = 0;
    YAML::Mark documentStart_;
    bool refused_ = false;
    Problems& problems_;
    std::vector<Level> open_;
};

// Where a comment starts inside brackets ({...} or [...]), or npos: an
// unquoted colour there, as in {color: #c8a26b}, hides the closing bracket,
// and the YAML reader's complaint ("end of map flow not found") comes lines
// later. Quotes are followed only where a value can start, so an
// apostrophe inside a word does not open one.
std::size_t commentInBrackets(std::string_view text) {
    int depth = 0;
    char quote = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const char before = i > 0 ? text[i - 1] : '\n';
        if (quote) {
            if (quote == '"' && c == '\\')
                ++i;
            else if (c == quote)
                quote = 0;
            continue;
        }
        const bool valueStart = before == ' ' || before == '\t' || before == '\n' || before == '[' || before == '{' ||
                                before == ',' || before == ':';
        if ((c == '"' || c == '\'') && valueStart)
            quote = c;
        else if (c == '[' || c == '{')
            ++depth;
        else if ((c == ']' || c == '}') && depth > 0)
            --depth;
        else if (c == '#' && (before == ' ' || before == '\t' || before == '\n')) {
            if (depth > 0) return i;
            i = std::min(text.find('\n', i), text.size()) - 1;  // the comment runs to the end of the line
        }
    }
    return std::string_view::npos;
}

}  // namespace

bool checkStructure(std::string_view text, const LoadLimits& limits, Problems& problems) {
    std::istringstream stream{std::string(text)};
    StructureCheck check(text, limits, problems);
    try {
        YAML::Parser parser(stream);
        int documents = 0;
        while (parser.HandleNextDocument(check)) {
            if (++documents > 1) {
                const YAML::Mark& mark = check.documentStart();
                problems.add(oneBased(mark.line), oneBased(mark.column),
                             "the file holds more than one YAML document ('---'); a scene is one document");
                return false;
            }
        }
        if (documents == 0) {
            problems.add(1, 1, "the file holds no YAML document; a scene starts with 'format: jacobs-ladder/1'");
            return false;
        }
    } catch (const Abandoned&) {
        return false;
    } catch (const YAML::Exception& e) {
        const bool unclosed = e.msg.find("flow not found") != std::string::npos;  // "end of map flow not found"
        if (const std::size_t hash = unclosed ? commentInBrackets(text) : std::string_view::npos;
            hash != std::string_view::npos) {
            const auto [line, column] = position(text, hash);
            problems.add(line, column,
                         "'#' starts a comment, so the rest of this line is not read and the bracket before it is "
                         "never closed; a colour goes in quotes: \"#c8a26b\"");
            return false;
        }
        if (const auto key = overlongKey(text)) {
            const auto [line, column] = position(text, key->first);
            problems.add(
                line, column,
                "a key of " + std::to_string(key->second) + " characters: YAML reads a key of at most 1024 characters");
            return false;
        }
        // yaml-cpp's words for a tab in the indentation do not say "tab".
        const bool tabIndent = text.starts_with('\t') || text.find("\n\t") != std::string_view::npos;
        problems.add(oneBased(e.mark.line), oneBased(e.mark.column),
                     "malformed YAML: " + e.msg + (tabIndent ? " (tabs cannot indent YAML; use spaces)" : ""));
        return false;
    }
    return !check.refused();
}

}  // namespace jl
