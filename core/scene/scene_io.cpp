// Loading and saving scene files: the file-system side (sizes, kinds of
// file, atomic replacement) and the order of the checks. No exception leaves
// this file: every failure becomes a diagnostic.
#include "jl/scene/scene_io.h"

#include "jl/base/output_file.h"
#include "problems.h"
#include "scene_read.h"
#include "yaml_prepass.h"

#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/node/parse.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <new>

namespace jl {

namespace {

SceneLoad failed(Problems& problems) { return {std::nullopt, problems.take()}; }

std::string tooLarge(const LoadLimits& limits) {
    const std::size_t mib = limits.maxFileBytes >> 20;
    return "the file is larger than " +
           (mib ? std::to_string(mib) + " MiB" : std::to_string(limits.maxFileBytes) + " bytes") +
           "; refusing to read it";
}

SceneLoad parseChecked(std::string_view text, const LoadLimits& limits, Problems& problems) {
    if (text.empty() || text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
        problems.add(1, 1, "the file is empty; a scene starts with 'format: jacobs-ladder/1'");
        return failed(problems);
    }
    if (!checkText(text, limits, problems)) return failed(problems);
    const bool readable = checkStructure(text, limits, problems);
    if (!readable) return failed(problems);
    const YAML::Node root = YAML::Load(std::string(text));
    std::optional<Scene> scene = readScene(root, limits, problems);
    if (!problems.empty()) return failed(problems);  // duplicate keys found by the first pass
    return {std::move(scene), {}};
}

}  // namespace

SceneLoad parseScene(std::string_view text, const std::string& fileNameForMessages, const LoadLimits& limits) {
    Problems problems(fileNameForMessages, limits.maxErrors);
    try {
        if (text.size() > limits.maxFileBytes) {
            problems.add(0, 0, tooLarge(limits));
            return failed(problems);
        }
        return parseChecked(text, limits, problems);
    } catch (const YAML::Exception& e) {
        problems.add(e.mark.line + 1, e.mark.column + 1, "malformed YAML: " + e.msg);
    } catch (const std::bad_alloc&) {
        problems.add(0, 0, "out of memory while reading the file");
    } catch (const std::exception& e) {
        problems.add(0, 0, std::string("cannot read the file: ") + e.what());
    }
    return failed(problems);
}

namespace {

// The file's text, or a whole-file problem. Only regular files are read:
// a FIFO or a device could block or never end.
std::optional<std::string> readFile(const std::string& path, const LoadLimits& limits, Problems& problems) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status)) {
        problems.add(0, 0, "cannot open the file: " + (ec ? ec.message() : std::string("it does not exist")));
        return std::nullopt;
    }
    if (fs::is_directory(status)) {
        problems.add(0, 0, "this is a directory, not a scene file");
        return std::nullopt;
    }
    if (!fs::is_regular_file(status)) {
        problems.add(0, 0, "this is not a regular file");
        return std::nullopt;
    }
    const auto size = fs::file_size(path, ec);
    if (!ec && size > limits.maxFileBytes) {
        problems.add(0, 0, tooLarge(limits));
        return std::nullopt;
    }
    std::ifstream in(path, std::ios::binary);
    std::string text;
    if (in) text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in && !in.eof()) {
        problems.add(0, 0, std::string("cannot read the file: ") + std::strerror(errno));
        return std::nullopt;
    }
    return text;
}

}  // namespace

SceneLoad loadScene(const std::string& path, const LoadLimits& limits) {
    Problems problems(path, limits.maxErrors);
    try {
        const std::optional<std::string> text = readFile(path, limits, problems);
        if (!text) return failed(problems);
        return parseScene(*text, path, limits);
    } catch (const std::exception& e) {
        problems.add(0, 0, std::string("cannot read the file: ") + e.what());
        return failed(problems);
    }
}

std::optional<Diagnostic> saveScene(const Scene& scene, const std::string& path) {
    std::string text;
    try {
        text = sceneToYaml(scene);
    } catch (const std::exception& e) {
        return Diagnostic{path, 0, 0, std::string("cannot save: ") + e.what()};
    }
    if (text.empty()) return Diagnostic{path, 0, 0, "cannot save: the scene could not be written as YAML"};
    if (const std::string error = writeWholeFile(path, text); !error.empty())
        return Diagnostic{path, 0, 0, "cannot save: " + error};
    return std::nullopt;
}

}  // namespace jl
