// The studio's JSON API (docs/studio.md): each request body → one response body, independent
// of HTTP so the same functions serve the server and its tests. Models come back as base64 GLB
// inside the JSON, with the stats or metadata the CLI prints or writes.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace ramus::studio {

/// What one request may cost. Size limits bound the work of every stage (a derivation cannot
/// outgrow maxModules, colonization maxPoints and the config's iterations, …); the time budget
/// is checked between stages, so a request stops at the first stage boundary past it.
struct StudioLimits {
    std::size_t maxBodyBytes = 1u << 20;      ///< request body (bytes)
    std::size_t maxModules = 2'000'000;       ///< L-system word (modules)
    std::size_t maxMemoryBytes = 256u << 20;  ///< L-system words (DeriveOptions::maxMemoryBytes)
    int maxDerivations = 64;                  ///< L-system derivation steps
    std::size_t maxPoints = 200'000;          ///< colonization attraction points
    int maxIterations = 2'000;                ///< colonization iterations
    std::size_t maxNodes = 1'000'000;         ///< colonization nodes of all trees
    std::size_t maxTriangles = 4'000'000;     ///< triangles of one response's meshes
    int maxSkeletons = 32;                    ///< skeletons per request
    double timeSeconds = 10.0;                ///< wall time per request
    std::size_t maxShownPoints = 20'000;      ///< attraction points sent back for display
};

/// A request the API refuses: HTTP status (400 bad input, 413 over a size limit, 408 over the
/// time budget) and a message; `where` holds file/line/column when the input was text.
class ApiError : public std::runtime_error {
public:
    ApiError(int status, const std::string& message, nlohmann::json where = nullptr)
        : std::runtime_error(message), status_(status), where_(std::move(where)) {}
    int status() const { return status_; }
    /// {"error": {"message", "status", and "file", "line", "column" when known}}.
    nlohmann::json body() const;

private:
    int status_;
    nlohmann::json where_;
};

/// POST /api/lsystem: {"text": ".lsys source", "derivations"?: n, "seed"?: s,
/// "set"?: {"NAME": value}, "mesh"?: {mesh overrides}} →
/// {"glb": base64, "stats": {modules, nodes, edges, polygons, vertices, triangles, *_seconds}}.
nlohmann::json lsystemRequest(const nlohmann::json& request, const StudioLimits& limits);

/// POST /api/colonize: {"config": {a colonize config, docs/colonize.md}, "seed"?: s} →
/// {"glb": base64, "stats": {...}, "points": [x, y, z, …] (at most maxShownPoints)}.
nlohmann::json colonizeRequest(const nlohmann::json& request, const StudioLimits& limits);

/// POST /api/skeleton: the inputs of `ramus skeleton` as JSON (docs/studio.md) →
/// {"skeletons": [{"name", "glb": base64, "metadata": {…}}]}.
nlohmann::json skeletonRequest(const nlohmann::json& request, const StudioLimits& limits);

/// GET /api/examples: {"lsystems": [{"name", "text"}], "colonize": [{"name", "config"}],
/// "species": [{"name", "class"}], "head_kinds": […], "resolutions": […]} from the examples
/// folder under `root`.
nlohmann::json examplesResponse(const std::string& root);

/// Standard base64 (RFC 4648 §4, with padding).
std::string base64(std::string_view bytes);

}  // namespace ramus::studio
