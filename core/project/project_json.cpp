// The project.json document in both directions: parseProject reads and validates it,
// serializeProject writes it. Every section's keys are the rows of its table (project/
// settings.h); this file holds the top level: the header, the sections and the lists.
#include "project/project.h"

#include <algorithm>
#include <array>
#include <type_traits>

#include "project/project_json_parts.h"
#include "project/project_migration.h"

namespace grass::core {

namespace {

using json::Json;
using settings::field;

constexpr std::string_view FORMAT_NAME = "grass-project";

// A list of named objects (layers, cameras, wind sources, colliders), each read by `Table()` and
// checked by `Check` (nullptr: no check).
struct ListSpec {
    std::string_view what;
    std::size_t maxItems;
};

template <const ListSpec& Spec, auto Table, auto Check, auto Member>
constexpr settings::Setting<Project> list(settings::Setting<Project> row) {
    using Item = typename settings::detail::Value<Member>::value_type;
    row.typeText = "array of objects";
    return settings::custom<Project>(
        row,
        [](json::Reader& reader, json::Object& top, std::string_view key, Project& project) {
            const auto readItem = [](json::Reader& r, const Json& node, const std::string& at,
                                     Item& item) {
                settings::readObject<Item>(r, node, at, Table(), Check, item);
            };
            if (const Json* node = top.find(key))
                json::readList(reader, *node, top.pointerTo(key), Spec.what, Spec.maxItems,
                               project.*Member, readItem);
        },
        [](const Project& project) -> Json {
            Json out = Json::array();
            for (const Item& item : project.*Member)
                out.push_back(settings::sectionJson(Table(), item));
            return out;
        });
}

// Format and version are checked by readHeader before anything else; the rows write them.
void readNothing(json::Reader&, json::Object&, std::string_view, Project&) {}
Json formatJson(const Project&) { return std::string(FORMAT_NAME); }
Json versionJson(const Project&) { return PROJECT_FORMAT_VERSION; }

constexpr ListSpec LAYERS{"layer", MAX_LAYERS};
constexpr ListSpec CAMERAS{"camera", MAX_CAMERAS};
constexpr ListSpec WIND{"wind source", MAX_WIND_SOURCES};
constexpr ListSpec COLLIDERS{"collider", MAX_COLLIDERS};

constexpr std::array PROJECT{
    settings::custom<Project>({.key = "format",
                               .typeText = "string",
                               .allowedText = "`\"grass-project\"`",
                               .defaultText = "**required**"},
                              readNothing, formatJson),
    settings::custom<Project>({.key = "version",
                               .typeText = "integer",
                               .allowedText = "`1` or `2`; older versions are raised to the "
                                              "newest as they are read (see [versions](#versions))",
                               .defaultText = "**required**"},
                              readNothing, versionJson),
    field<&Project::name>({.key = "name"}),
    field<&Project::seed>(
        {.key = "seed", .help = "seeds every layer's scattering (each layer its own stream)"}),
    settings::object<settings::mesh, nullptr, &Project::mesh>(
        {.key = "mesh",
         .allowedText = "see [mesh](#mesh)", .defaultText = "procedural plane"}),
    list<LAYERS, settings::layer, nullptr, &Project::layers>(
        {.key = "layers",
         .allowedText = "may be empty; see [layers](#layers)",
         .defaultText = "one layer with the defaults"}),
    list<CAMERAS, settings::camera, json::checkCamera, &Project::cameras>(
        {.key = "cameras",
         .allowedText = "at least one; see [cameras](#cameras)",
         .defaultText = "one camera with the defaults"}),
    settings::object<settings::sun, json::checkSun, &Project::sun>(
        {.key = "sun",
         .allowedText = "see [sun](#sun)", .defaultText = "defaults"}),
    settings::object<settings::lighting, json::checkLighting, &Project::lighting>(
        {.key = "lighting",
         .allowedText = "see [lighting](#lighting)", .defaultText = "defaults"}),
    settings::object<settings::render, json::checkRender, &Project::render>(
        {.key = "render",
         .allowedText = "see [render](#render)", .defaultText = "defaults"}),
    settings::object<settings::billboards, nullptr, &Project::billboards>(
        {.key = "billboards",
         .allowedText = "see [billboards](#billboards)", .defaultText = "defaults"}),
    settings::object<settings::physics, nullptr, &Project::physics>(
        {.key = "physics",
         .allowedText = "see [physics](#physics)", .defaultText = "defaults"}),
    list<WIND, settings::wind, json::checkWind, &Project::wind>(
        {.key = "wind",
         .allowedText = "see [wind](#wind)"}),
    list<COLLIDERS, settings::collider, nullptr, &Project::colliders>(
        {.key = "colliders",
         .allowedText = "see [colliders](#colliders)"}),
    settings::object<settings::snow, json::checkSnow, &Project::snow>(
        {.key = "snow",
         .allowedText = "see [snow](#snow)", .defaultText = "snow off"}),
};

void readHeader(json::Reader& reader, const Json& root) {
    // Format and version first: a file that is not a project (or is a newer one) should say
    // so, not list the keys this build does not know.
    const std::string readsVersion = "this build reads only versions " +
                                     std::to_string(json::OLDEST_PROJECT_VERSION) + " to " +
                                     std::to_string(PROJECT_FORMAT_VERSION);
    const auto format = root.find("format");
    if (format == root.end()) {
        reader.fail("/format", "missing required key (a grass project begins {\"format\": \"" +
                                   std::string(FORMAT_NAME) + "\", \"version\": " +
                                   std::to_string(PROJECT_FORMAT_VERSION) + ", ...})");
        return;
    }
    if (!format->is_string() || format->get_ref<const std::string&>() != FORMAT_NAME) {
        reader.fail("/format", "must be \"" + std::string(FORMAT_NAME) + "\" (got " +
                                   json::describeValue(*format) + "); not a grass project file");
        return;
    }
    const auto version = root.find("version");
    if (version == root.end()) {
        reader.fail("/version", "missing required key (" + readsVersion + ")");
        return;
    }
    if (!version->is_number_integer())
        reader.fail("/version", "must be an integer (got " + json::describeValue(*version) + "); " +
                                    readsVersion);
    else if (version->get<std::int64_t>() < json::OLDEST_PROJECT_VERSION ||
             version->get<std::int64_t>() > PROJECT_FORMAT_VERSION)
        reader.fail("/version", "unsupported version " + json::describeValue(*version) + " (" +
                                    readsVersion + ")");
}

void readProject(json::Reader& reader, Json& root, Project& project) {
    if (!root.is_object()) {
        reader.fail("", "a project file must be a JSON object {\"format\": \"" +
                            std::string(FORMAT_NAME) + "\", ...} (got " +
                            json::describeValue(root) + ")");
        return;
    }
    readHeader(reader, root);
    if (!reader.ok())
        return;
    if (const auto version = root["version"].get<std::int64_t>(); version < PROJECT_FORMAT_VERSION)
        json::migrateProject(root, version);
    settings::readSection(reader, root, "", settings::project(), project);
    if (reader.ok() && project.cameras.empty())
        reader.fail("/cameras", "must hold at least one camera");
}

std::string scalarText(const Json& value) {
    // Invalid UTF-8 in a name is replaced rather than thrown on.
    return value.dump(-1, ' ', false, Json::error_handler_t::replace);
}

// Like dump(2) but with arrays of numbers on one line ("[14.0, 7.0, 14.0]"), which reads
// better for vectors, colours and ranges.
void writeJson(std::string& out, const Json& value, std::size_t indent) {
    const std::string inner(indent + 2, ' ');
    if (value.is_object() && !value.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (const auto& item : value.items()) {
            out += inner + scalarText(Json(item.key())) + ": ";
            writeJson(out, item.value(), indent + 2);
            out += ++i < value.size() ? ",\n" : "\n";
        }
        out += std::string(indent, ' ') + "}";
    } else if (value.is_array() && !value.empty()) {
        const bool flat = std::none_of(value.begin(), value.end(),
                                       [](const Json& element) { return element.is_structured(); });
        out += flat ? "[" : "[\n";
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!flat)
                out += inner;
            writeJson(out, value[i], indent + 2);
            if (i + 1 < value.size())
                out += flat ? ", " : ",\n";
        }
        out += flat ? "]" : "\n" + std::string(indent, ' ') + "]";
    } else {
        out += scalarText(value);
    }
}

}  // namespace

std::span<const settings::Setting<Project>> settings::project() { return PROJECT; }

void json::checkAssetPath(json::Reader& reader, const std::string& pointer,
                          const std::string& path) {
    if (!reader.ok())
        return;
    const auto resolved = resolveAssetPath({}, path, pointer);
    if (!resolved)
        reader.fail(pointer, resolved.error().message);
}

double framebufferBytes(int width, int height, int msaaSamples) {
    // RGBA8 + DEPTH_COMPONENT32F per sample; resolved RGBA8, depth texture, read-back RGBA8.
    constexpr double BYTES_PER_SAMPLE = 4.0 + 4.0;
    constexpr double BYTES_PER_PIXEL = 4.0 + 4.0 + 4.0;
    const double samples = std::max(1, msaaSamples);
    return static_cast<double>(width) * static_cast<double>(height) *
           (BYTES_PER_SAMPLE * samples + BYTES_PER_PIXEL);
}

Result<Project> parseProject(std::string_view jsonText, const std::string& sourceName) {
    auto document = json::parseDocument(jsonText, sourceName);
    if (!document)
        return document.error();
    json::Reader reader(sourceName);
    Project project;
    readProject(reader, *document, project);
    if (!reader.ok())
        return reader.error();
    return project;
}

std::string serializeProject(const Project& project) {
    std::string text;
    writeJson(text, settings::sectionJson(settings::project(), project), 0);
    text += "\n";
    return text;
}

}  // namespace grass::core
