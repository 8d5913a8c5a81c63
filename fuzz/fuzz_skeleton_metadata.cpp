// libFuzzer target for the skeleton metadata loader (docs/skeleton.md, "Metadata"): any text must
// either parse or throw ramus::Error. An accepted design must build, and its metadata must read
// back to the same design (save/load regenerates the same skeleton). Crashes, sanitizer reports,
// other exceptions and hangs are bugs.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "ramus/error.hpp"
#include "ramus/skeleton.hpp"
#include "ramus/skeleton_io.hpp"

namespace {

bool sameDesign(const ramus::SkeletonDesign& a, const ramus::SkeletonDesign& b) {
    return a.featurePoint == b.featurePoint && a.neckVertebrae == b.neckVertebrae &&
           a.frontBackVertebrae == b.frontBackVertebrae &&
           a.rearBackVertebrae == b.rearBackVertebrae && a.tailVertebrae == b.tailVertebrae &&
           a.ribs == b.ribs && a.limbs == b.limbs && a.wingAngles == b.wingAngles &&
           a.heelDraw == b.heelDraw && a.headKind == b.headKind && a.spacing == b.spacing &&
           a.grammarSeed == b.grammarSeed && a.metresPerPixel == b.metresPerPixel;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    ramus::LoadedSkeleton loaded;
    try {
        loaded = ramus::parseSkeletonMetadata(text, "fuzz.json");
    } catch (const ramus::Error&) {
        return 0;
    }
    ramus::Skeleton skeleton;
    try {
        skeleton = ramus::buildSkeleton(loaded.design);
    } catch (const ramus::Error&) {
        return 0;  // a design the metadata checks let through but the grammar refuses: reported
    }
    const std::string again =
        ramus::skeletonMetadataJson(loaded.design, skeleton, loaded.name, loaded.seed);
    const ramus::LoadedSkeleton back = ramus::parseSkeletonMetadata(again, "back.json");
    if (!sameDesign(back.design, loaded.design) || back.name != loaded.name ||
        back.seed != loaded.seed) {
        __builtin_trap();
    }
    return 0;
}
