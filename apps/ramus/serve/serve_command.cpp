// `ramus serve`: the studio — a local HTTP server with the JSON API (studio_api.hpp) and the
// web page (web/), docs/studio.md. Binds to 127.0.0.1 unless told otherwise.
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "ramus/error.hpp"
#include "serve/studio_api.hpp"
#include "serve/studio_request.hpp"

// Last: httplib.h pulls in <resolv.h>, whose `_res` macro breaks Eigen's headers.
#include <httplib.h>

namespace ramus::cli {
namespace {

namespace fs = std::filesystem;

struct ServeOptions {
    std::string host = "127.0.0.1";
    int port = 8080;
    int jobs = 2;
    int queue = 16;
    std::string root;
    studio::StudioLimits limits;
    std::size_t maxMemoryMiB = studio::StudioLimits{}.maxMemoryBytes >> 20;
};

/// Bounds concurrent generation: at most `jobs` run, at most `queue` wait; more are refused
/// (the server stays responsive instead of piling up work).
class GenerationGate {
public:
    GenerationGate(int jobs, int queue) : jobs_(jobs), queue_(queue) {}

    /// Waits for a slot; false when the queue is full.
    bool enter() {
        std::unique_lock lock(mutex_);
        if (running_ >= jobs_ && waiting_ >= queue_) return false;
        ++waiting_;
        free_.wait(lock, [&] { return running_ < jobs_; });
        --waiting_;
        ++running_;
        return true;
    }
    void leave() {
        {
            std::lock_guard lock(mutex_);
            --running_;
        }
        free_.notify_one();
    }

private:
    std::mutex mutex_;
    std::condition_variable free_;
    int jobs_, queue_, running_ = 0, waiting_ = 0;
};

// Content types carry "; charset=utf-8", which is also what keeps cpp-httplib from compressing
// them: it brotli/gzip-compresses exact "application/json", "text/…" types for clients that
// accept it, which costs seconds per megabyte of GLB at brotli's default level and buys
// nothing on a local connection.
constexpr const char* kJsonType = "application/json; charset=utf-8";

void sendJson(httplib::Response& res, int status, const nlohmann::json& body) {
    res.status = status;
    res.set_content(body.dump(), kJsonType);
}

void setStaticTypes(httplib::Server& server) {
    server.set_file_extension_and_mimetype_mapping("html", "text/html; charset=utf-8");
    server.set_file_extension_and_mimetype_mapping("js", "text/javascript; charset=utf-8");
    server.set_file_extension_and_mimetype_mapping("mjs", "text/javascript; charset=utf-8");
    server.set_file_extension_and_mimetype_mapping("css", "text/css; charset=utf-8");
    server.set_file_extension_and_mimetype_mapping("json", kJsonType);
}

/// The folder holding web/ and examples/: --root, else the working directory or the source
/// tree the binary was built in (build/<type>/ramus → ../..).
std::string findRoot(const std::string& given) {
    if (!given.empty()) return given;
    std::vector<fs::path> candidates = {fs::current_path()};
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        candidates.push_back(exe.parent_path().parent_path().parent_path());
        candidates.push_back(exe.parent_path().parent_path());
    }
    for (const fs::path& dir : candidates) {
        if (fs::exists(dir / "examples") && fs::exists(dir / "web")) return dir.string();
    }
    return fs::current_path().string();
}

using Endpoint = nlohmann::json (*)(const nlohmann::json&, const studio::StudioLimits&);

/// POST handler: parse the body, run the endpoint inside the gate, answer JSON.
httplib::Server::Handler post(Endpoint endpoint, GenerationGate& gate,
                              const studio::StudioLimits& limits) {
    return [endpoint, &gate, &limits](const httplib::Request& req, httplib::Response& res) {
        nlohmann::json request;
        try {
            request = nlohmann::json::parse(req.body);
        } catch (const nlohmann::json::parse_error& e) {
            const std::string message = "request body: malformed JSON at byte " +
                                        std::to_string(e.byte) + "; expected a JSON object";
            sendJson(res, 400, studio::ApiError(400, message).body());
            return;
        } catch (const nlohmann::json::exception& e) {  // e.g. a number beyond double range
            const std::string message =
                std::string("request body: ") + e.what() + "; expected finite numbers";
            sendJson(res, 400, studio::ApiError(400, message).body());
            return;
        }
        if (!gate.enter()) {
            sendJson(res, 503,
                     studio::ApiError(503, "the server is busy; expected fewer requests at once")
                         .body());
            return;
        }
        try {
            sendJson(res, 200, endpoint(request, limits));
        } catch (const studio::ApiError& e) {
            sendJson(res, e.status(), e.body());
        } catch (const Error& e) {
            const studio::ApiError error = studio::badRequest(e);
            sendJson(res, error.status(), error.body());
        } catch (const std::exception& e) {
            sendJson(res, 500, studio::ApiError(500, e.what()).body());
        }
        gate.leave();
    };
}

void run(const ServeOptions& o) {
    httplib::Server server;
    GenerationGate gate(o.jobs, o.queue);
    const std::string root = findRoot(o.root);
    // Connection threads: enough for the queue plus the page's static files.
    const int threads = o.jobs + o.queue + 4;
    server.new_task_queue = [threads] { return new httplib::ThreadPool(threads); };
    server.set_payload_max_length(o.limits.maxBodyBytes);
    server.set_error_handler([&o](const httplib::Request&, httplib::Response& res) {
        if (!res.body.empty()) return;
        std::string message = "HTTP " + std::to_string(res.status);
        if (res.status == 413) {
            message = "request body too large; expected at most " +
                      std::to_string(o.limits.maxBodyBytes) + " bytes";
        } else if (res.status == 404) {
            message = "not found";
        }
        sendJson(res, res.status, studio::ApiError(res.status, message).body());
    });
    server.Get("/api/examples", [root](const httplib::Request&, httplib::Response& res) {
        sendJson(res, 200, studio::examplesResponse(root));
    });
    server.Post("/api/lsystem", post(studio::lsystemRequest, gate, o.limits));
    server.Post("/api/colonize", post(studio::colonizeRequest, gate, o.limits));
    server.Post("/api/skeleton", post(studio::skeletonRequest, gate, o.limits));
    setStaticTypes(server);
    if (fs::exists(fs::path(root) / "web")) server.set_mount_point("/", root + "/web");

    const int port = o.port == 0 ? server.bind_to_any_port(o.host)
                                 : (server.bind_to_port(o.host, o.port) ? o.port : -1);
    if (port < 0) {
        throw Error("cannot listen on " + o.host + ":" + std::to_string(o.port) +
                    "; expected a free port (try --port 0 for any)");
    }
    std::printf("ramus studio: http://%s:%d/\n", o.host.c_str(), port);
    std::fflush(stdout);
    server.listen_after_bind();
}

}  // namespace

void addServeCommand(CLI::App& app) {
    auto o = std::make_shared<ServeOptions>();
    CLI::App* cmd = app.add_subcommand("serve", "run the studio: a local web page and JSON API");
    cmd->add_option("--host", o->host, "address to bind (default 127.0.0.1: this machine only)");
    cmd->add_option("--port", o->port, "port (0 = any free port; the address is printed)")
        ->check(CLI::Range(0, 65535))
        ->capture_default_str();
    cmd->add_option("--jobs", o->jobs, "models generated at once")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    cmd->add_option("--queue", o->queue, "requests that may wait for a job; more get HTTP 503")
        ->check(CLI::Range(0, 1024))
        ->capture_default_str();
    cmd->add_option("--root", o->root, "folder with web/ and examples/ (default: found)");
    cmd->add_option("--time-limit", o->limits.timeSeconds, "seconds per request")
        ->check(finiteNumber(0.0, false, 1e6, "a number of seconds in (0, 1e6]", true))
        ->capture_default_str();
    cmd->add_option("--max-modules", o->limits.maxModules, "L-system word limit per request")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-memory", o->maxMemoryMiB, "L-system word memory per request, in MiB")
        ->check(CLI::Range(std::size_t{1}, std::size_t{1} << 20))
        ->capture_default_str();
    cmd->add_option("--max-derivations", o->limits.maxDerivations,
                    "L-system derivation steps per request")
        ->check(CLI::Range(0, 1000))
        ->capture_default_str();
    cmd->add_option("--max-points", o->limits.maxPoints, "attraction points per request")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-iterations", o->limits.maxIterations,
                    "colonization iterations per request")
        ->check(CLI::Range(1, 100'000'000))
        ->capture_default_str();
    cmd->add_option("--max-nodes", o->limits.maxNodes, "colonization nodes per request")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-triangles", o->limits.maxTriangles, "triangles per response")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--max-skeletons", o->limits.maxSkeletons, "skeletons per request")
        ->check(CLI::Range(1, 10'000))
        ->capture_default_str();
    cmd->add_option("--max-body", o->limits.maxBodyBytes, "request body limit in bytes")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->callback([o] {
        o->limits.maxMemoryBytes = o->maxMemoryMiB << 20;
        run(*o);
    });
}

}  // namespace ramus::cli
