// Fuzz target: project.json through loadProject, as the editor and every CLI command open a
// project. A project that loads must also survive the save round trip project.h promises:
// serializeProject, then parseProject, gives the same Project.
#include <string>

#include "fuzz_scratch.h"
#include "project/project.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace grass;
    const std::filesystem::path file = fuzz::scratchDir() / "project.json";
    fuzz::writeBytes(file, {data, size});
    const auto loaded = core::loadProject(file);
    if (!loaded) {
        fuzz::checkError(loaded.error());
    } else {
        const std::string saved = core::serializeProject(loaded->project);
        const auto again = core::parseProject(saved, "saved project.json");
        if (!again)
            fuzz::fail("a loaded project does not load once saved: " + again.error().str());
        if (!(*again == loaded->project))
            fuzz::fail("a loaded project changes when saved and loaded again:\n" + saved);
    }
    fuzz::clearScratch();
    return 0;
}
