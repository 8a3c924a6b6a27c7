// Saved projects keep opening: a project.json of an older format version is raised to the
// current one, step by step, before it is read, so the reader (and its tables of settings) know
// only the newest version. Each change to what project.json holds or accepts raises
// PROJECT_FORMAT_VERSION and adds a step here.
#pragma once

#include <cstdint>

#include "project/json_reader.h"

namespace grass::core::json {

// The oldest version this build still opens.
inline constexpr std::int64_t OLDEST_PROJECT_VERSION = 1;

// Raises `root`, a project document of `version` (OLDEST_PROJECT_VERSION <= version <=
// PROJECT_FORMAT_VERSION), to the current version.
void migrateProject(Json& root, std::int64_t version);

}  // namespace grass::core::json
