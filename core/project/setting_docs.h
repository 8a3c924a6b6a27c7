// docs/project-format.md's tables, written from the tables of settings (project/settings.h), so
// the doc says what the reader accepts: a test checks the doc holds each table as written here.
#pragma once

#include <string>
#include <vector>

namespace grass::core::settings {

struct DocTable {
    std::string section;   // "snow", "layers/blade": where the doc shows it
    std::string markdown;  // "| key | type | default | allowed |\n|---|...\n| `enabled` | ..."
};

// Every section of project.json in document order, with the defaults of a new project.
std::vector<DocTable> projectFormatTables();

}  // namespace grass::core::settings
