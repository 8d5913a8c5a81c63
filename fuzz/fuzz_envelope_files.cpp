// libFuzzer target for the files a colonization config points at (docs/colonize.md,
// "Envelopes"): attraction-point files (XYZ, CSV, ASCII PLY) and closed OBJ meshes. The first
// byte picks the reader ('x' XYZ, 'c' CSV, 'p' PLY, 'o' OBJ; other bytes by their value modulo
// 4), the rest is the file's text. Accepted points must all be finite; an accepted mesh volume
// is queried (inside tests, segment hits, rejection sampling) and every sampled point must lie
// inside it. Only ramus::Error may escape the library; anything else (crash, sanitizer report,
// other exception, hang) is a bug.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "ramus/envelope.hpp"
#include "ramus/error.hpp"
#include "ramus/mesh_volume.hpp"

namespace {

enum class Reader { Xyz, Csv, Ply, Obj };

Reader readerFor(std::uint8_t selector) {
    switch (selector) {
        case 'x':
            return Reader::Xyz;
        case 'c':
            return Reader::Csv;
        case 'p':
            return Reader::Ply;
        case 'o':
            return Reader::Obj;
        default:
            return static_cast<Reader>(selector % 4);
    }
}

void fuzzPoints(const std::string& text, const char* format) {
    std::vector<ramus::Vec3> points;
    try {
        points = ramus::parsePoints(text, format, "fuzz.points");
    } catch (const ramus::Error&) {
        return;
    }
    for (const ramus::Vec3& p : points) {
        if (!p.allFinite()) __builtin_trap();
    }
}

void fuzzObj(const std::string& text) {
    std::shared_ptr<const ramus::MeshVolume> volume;
    try {
        volume = std::make_shared<const ramus::MeshVolume>(ramus::parseObjVolume(text, "fuzz.obj"));
    } catch (const ramus::Error&) {
        return;
    }
    const ramus::Aabb box = volume->bounds();
    const ramus::Vec3 centre = (box.min + box.max) / 2;
    (void)volume->contains(centre);
    (void)volume->segmentHits(box.min, box.max);
    ramus::Envelope envelope;
    envelope.shape.kind = ramus::ShapeKind::Mesh;
    envelope.shape.mesh = volume;
    envelope.pointCount = 5;
    std::vector<ramus::Vec3> points;
    try {
        points = ramus::sampleEnvelope(envelope, 1);
    } catch (const ramus::Error&) {
        return;  // rejection sampling gave up: a reported error
    }
    for (const ramus::Vec3& p : points) {
        if (!p.allFinite() || !volume->contains(p)) __builtin_trap();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    switch (readerFor(data[0])) {
        case Reader::Xyz:
            fuzzPoints(text, "xyz");
            break;
        case Reader::Csv:
            fuzzPoints(text, "csv");
            break;
        case Reader::Ply:
            fuzzPoints(text, "ply");
            break;
        case Reader::Obj:
            fuzzObj(text);
            break;
    }
    return 0;
}
