// ramus — procedural plants and vertebrate skeletons as 3D assets.
// Exit codes: 0 success, 1 bad input or failed generation (`error: …` on stderr), 2 bad usage.
#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "ramus/error.hpp"
#include "ramus/memory_policy.hpp"

int main(int argc, char** argv) {
    ramus::keepFreedMemoryForReuse();  // many items per process: reuse, do not re-fault
    CLI::App app{"ramus: procedural plants and vertebrate skeletons as 3D assets", "ramus"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "ramus 0.1.0");
    ramus::cli::addLsystemCommand(app);
    ramus::cli::addRenderCommand(app);
    ramus::cli::addSpeciesCommand(app);
    ramus::cli::addPcaCommand(app);
    ramus::cli::addColonizeCommand(app);
    ramus::cli::addSkeletonCommand(app);
    ramus::cli::addBonesCommand(app);
    ramus::cli::addServeCommand(app);
    ramus::cli::addBatchCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;
    } catch (const ramus::Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
    return 0;
}
