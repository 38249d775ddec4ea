// SPDX-License-Identifier: GPL-3.0-or-later
// Golden-directory cases: a folder per case under tests/data holding one JSON file of a kind
// (segmentation.json, stroke.json), whose grids are rows of whitespace-separated tokens.
#pragma once

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace core_test {

/** Whitespace-separated tokens of one grid row. */
inline std::vector<std::string> tokens(const std::string& row) {
    std::istringstream in(row);
    std::vector<std::string> out;
    for (std::string t; in >> t;)
        out.push_back(t);
    return out;
}

/** tests/data/<case>/<fileName> of every case folder that has one, in name order. */
inline std::vector<std::filesystem::path> goldenFiles(const std::string& fileName) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(LAYERPAINT_TEST_DATA))
        if (entry.is_directory() && std::filesystem::exists(entry.path() / fileName))
            files.push_back(entry.path() / fileName);
    std::sort(files.begin(), files.end());
    return files;
}

/** The case's name: its folder's. */
inline std::string goldenCaseName(const std::filesystem::path& file) {
    return file.parent_path().filename().string();
}

/** Names each test of a golden file parameter after its case. */
inline std::string goldenTestName(const testing::TestParamInfo<std::filesystem::path>& param) {
    return goldenCaseName(param.param);
}

/** The names of the cases that have a fileName. */
inline std::vector<std::string> goldenCaseNames(const std::string& fileName) {
    std::vector<std::string> names;
    for (const auto& file : goldenFiles(fileName))
        names.push_back(goldenCaseName(file));
    return names;
}

} // namespace core_test
