#include "walls/bake_writer.h"

#include "walls/content_hash.h"
#include "walls/depth_file.h"

#include "config/error.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#include <utility>

namespace cavewall::walls {

namespace {

// The content check of a file just written, read back from the disk.
std::uint64_t writtenHash(const std::filesystem::path& file) {
    const std::optional<std::uint64_t> hash = contentHashFile(file);
    if (!hash) throw Error(file.string() + ": cannot read the written file back to hash it");
    return *hash;
}
constexpr int kWorkerNice = 4;  // nice steps below the thread that made the writer
}  // namespace

BakeWriter::BakeWriter(std::filesystem::path folder, int jobs, MipFileOptions options, TextureFormat format)
    : _folder(std::move(folder)), _options(std::move(options)), _format(format),
      _maxQueued(std::size_t(4 * std::max(1, jobs))) {
    for (int i = 0; i < std::max(1, jobs); ++i) _threads.emplace_back([this] { worker(); });
}

BakeWriter::~BakeWriter() {
    {
        std::lock_guard lock(_mutex);
        _stop = true;
    }
    _changed.notify_all();
    for (std::thread& t : _threads) t.join();
}

void BakeWriter::submit(walls::BakedTexture entry, scenes::Image image) {
    std::unique_lock lock(_mutex);
    _changed.wait(lock, [&] { return _queue.size() < _maxQueued || _error; });
    if (_error) std::rethrow_exception(_error);
    _queue.push_back({std::move(entry), std::move(image), std::nullopt});
    _changed.notify_all();
}

void BakeWriter::submit(walls::BakedTexture entry, scenes::Image image, DepthImage depth) {
    if (entry.depthFile.empty()) throw Error(entry.file + ": a depth wall's texture needs a depth file name, got none");
    std::unique_lock lock(_mutex);
    _changed.wait(lock, [&] { return _queue.size() < _maxQueued || _error; });
    if (_error) std::rethrow_exception(_error);
    _queue.push_back({std::move(entry), std::move(image), std::move(depth)});
    _changed.notify_all();
}

std::vector<walls::BakedTexture> BakeWriter::takeDone(bool wait) {
    std::unique_lock lock(_mutex);
    if (wait) _changed.wait(lock, [&] { return !_done.empty() || _error || (_queue.empty() && _busy == 0); });
    if (_error) std::rethrow_exception(_error);
    return std::exchange(_done, {});
}

BakeWriter::Times BakeWriter::times() const {
    std::lock_guard lock(_mutex);
    return _times;
}

int BakeWriter::pending() const {
    std::lock_guard lock(_mutex);
    return static_cast<int>(_queue.size()) + _busy;
}

void BakeWriter::worker() {
    // Below the rendering thread and llvmpipe's: a cold bake is bound by the GL thread's draws
    // (the critical path), while encoding can fill whatever CPU the draws leave; a full queue
    // lets the workers catch up. Best effort: without the right to it, the priority stays.
    const pid_t self = static_cast<pid_t>(::syscall(SYS_gettid));
    errno = 0;
    const int nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(self));
    if (errno == 0) ::setpriority(PRIO_PROCESS, static_cast<id_t>(self), std::min(19, nice + kWorkerNice));
    for (;;) {
        Job job;
        {
            std::unique_lock lock(_mutex);
            _changed.wait(lock, [&] { return _stop || !_queue.empty(); });
            if (_queue.empty()) return;
            job = std::move(_queue.front());
            _queue.pop_front();
            ++_busy;
        }
        _changed.notify_all();  // a submit may wait for room
        std::exception_ptr error;
        Times spent;
        using Clock = std::chrono::steady_clock;
        Clock::time_point mark = Clock::now();
        auto lap = [&mark](double& into) {
            const Clock::time_point now = Clock::now();
            into += std::chrono::duration<double>(now - mark).count();
            mark = now;
        };
        try {
            const std::filesystem::path file = _folder / job.entry.file;
            const std::vector<scenes::Image> levels = mipChainOfPremultiplied(job.image);
            lap(spent.mips);
            if (_format == TextureFormat::Rgba8)
                writeMipFile(file, levels, _options);
            else
                writeBlockFile(file, encodeLevels(levels, storedFormat(levels.front(), _format)));
            lap(spent.encode);
            std::error_code ec;
            job.entry.bytes = std::filesystem::file_size(file, ec);
            if (ec) throw Error(file.string() + ": cannot read the size of the written file (" + ec.message() + ")");
            // The time first: a change while hashing then shows as a changed time next start.
            walls::stampTexture(_folder, job.entry);
            job.entry.hash = writtenHash(file);
            lap(spent.hash);
            if (job.depth) {
                // What the march reads (walls::marchDepths): a quarter of the texels when both
                // sides are even.
                *job.depth = marchDepths(std::move(*job.depth));
                const std::filesystem::path depthFile = _folder / job.entry.depthFile;
                writeDepthFile(depthFile, *job.depth);
                lap(spent.encode);
                job.entry.depthBytes = std::filesystem::file_size(depthFile, ec);
                if (ec)
                    throw Error(depthFile.string() + ": cannot read the size of the written file (" + ec.message() +
                                ")");
                job.entry.depthHash = writtenHash(depthFile);
                job.entry.depthRange = depthRange(*job.depth);
                lap(spent.hash);
            }
        } catch (...) {
            error = std::current_exception();
        }
        {
            std::lock_guard lock(_mutex);
            --_busy;
            _times.mips += spent.mips;
            _times.encode += spent.encode;
            _times.hash += spent.hash;
            if (error && !_error) _error = error;
            if (!error) _done.push_back(std::move(job.entry));
        }
        _changed.notify_all();
    }
}

}  // namespace cavewall::walls
