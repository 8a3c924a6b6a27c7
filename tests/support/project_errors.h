// The check every project-format test makes of a rejected document: one line that names the
// file it was parsed as, the JSON pointer at fault and the problem.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "project/project.h"

namespace grass::test {

inline void expectProjectError(const std::string& text, const std::string& source,
                               const std::string& pointer, const std::string& problem) {
    const auto parsed = core::parseProject(text, source);
    ASSERT_FALSE(parsed.ok()) << "accepted: " << text;
    const std::string error = parsed.error().str();
    EXPECT_NE(error.find(source), std::string::npos) << error;
    EXPECT_NE(error.find(pointer + ": "), std::string::npos) << error;
    EXPECT_NE(error.find(problem), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "not one line: " << error;
}

// A minimal project document whose top-level object `key` holds `members` (JSON text without
// the braces), and the error check on it: what each section's tests ("snow", "lighting") share.
inline std::string documentWithObject(const std::string& key, const std::string& members) {
    return R"({"format": "grass-project", "version": 1, ")" + key + R"(": {)" + members + "}}";
}

inline void expectObjectError(const std::string& key, const std::string& members,
                              const std::string& source, const std::string& pointer,
                              const std::string& problem) {
    expectProjectError(documentWithObject(key, members), source, pointer, problem);
}

}  // namespace grass::test
