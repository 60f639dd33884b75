// ingest_raster: the write pass. Cells run in parallel on a oneTBB arena; each thread has its own
// GDAL handles and PROJ transforms (TileResampler); each cell's tile and run record are committed
// in one batch (a few cells per batch), so a killed ingest resumes with --resume to the same bits.
#include "gdal/raster_ingest.h"

#include <spdlog/spdlog.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <exception>
#include <filesystem>
#include <future>
#include <mutex>
#include <numeric>
#include <optional>

#include "core/data_footprint.h"
#include "core/error.h"
#include "core/samples.h"
#include "gdal/tile_resampler.h"
#include "runtime/progress.h"
#include "store/created_store.h"

namespace maquette {
namespace {

// Where the batches of `cells` (sorted) start, and their end: each batch holds the cells of one
// parent (up to four, consecutive in id order). A commit costs about as much as a tile's work
// (see the store benchmark), so a few cells per batch; and a batch holding all four children of
// a parent writes the parent's overview from its tiles in memory (Store::Batch), so that
// update_overviews need not read the base tiles back.
std::vector<size_t> sibling_batches(const std::vector<CellId>& cells) {
  std::vector<size_t> starts;
  for (size_t i = 0; i < cells.size(); ++i)
    if (i == 0 || cells[i].level() == 0 || cells[i].parent() != cells[i - 1].parent())
      starts.push_back(i);
  starts.push_back(cells.size());
  return starts;
}

// The batches of `starts` (from sibling_batches), those with most cells first, in id order
// otherwise: handed out one by one in this order, the run ends with the smallest batches rather
// than with one thread finishing a batch of four cells while the others wait.
std::vector<size_t> largest_first(const std::vector<size_t>& starts) {
  std::vector<size_t> order(starts.size() - 1);
  std::iota(order.begin(), order.end(), size_t(0));
  const auto size = [&](size_t b) { return starts[b + 1] - starts[b]; };
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return size(a) > size(b); });
  return order;
}

// from_tile(tile, dtype, nodata) without its per-sample conversion through double and libm's
// round: the same bytes (NaN -> nodata; integer dtypes rounded half away from zero and clamped),
// into `raw`, whose storage a thread reuses from tile to tile.
void to_raw(const Tile<float>& tile, DType dtype, const double* nodata, RawTile& raw) {
  raw.dtype = dtype;
  raw.size = tile.size();
  raw.channels = tile.channels();
  raw.bytes.resize(raw.sample_count() * dtype_size(dtype));
  const std::span<const float> in = tile.data();
  visit_dtype(dtype, [&]<typename S>(std::type_identity<S>) {
    const S fill = cast_sample<S>(nodata ? *nodata : std::numeric_limits<double>::quiet_NaN());
    std::byte* out = raw.bytes.data();
    for (size_t i = 0; i < in.size(); ++i, out += sizeof(S)) {
      const float v = in[i];
      S s = fill;
      if constexpr (std::is_floating_point_v<S>) {
        if (!std::isnan(v)) s = S(v);  // float32 and float64 hold every float exactly
      } else if (!std::isnan(v)) {
        constexpr double lo = double(std::numeric_limits<S>::min()),
                         hi = double(std::numeric_limits<S>::max());
        const double d = v;
        s = d <= lo   ? std::numeric_limits<S>::min()
            : d >= hi ? std::numeric_limits<S>::max()
                      : S(d < 0 ? -int64_t(0.5 - d) : int64_t(d + 0.5));
      }
      std::memcpy(out, &s, sizeof(S));
    }
  });
}

// A failed ingest leaves the store as it was where it can: a store it created is removed, a
// layer it created is dropped with its run; a layer that existed before stays marked incomplete
// (its old tiles may be overwritten), for --resume to finish.
// `untouched`: the layer as it was, complete, when the ingest committed none of its tiles: it is
// given back its definition (the footprint) and is readable again, not left incomplete.
void undo_failed_ingest(std::unique_ptr<Store> store, const std::string& layer, int64_t run,
                        bool new_layer, const std::optional<LayerInfo>& untouched) {
  const std::string path = store->path();
  try {
    if (store->created()) {
      remove_if_created(std::move(store));
    } else if (new_layer) {
      store->drop_layer(layer, run);
    } else if (untouched) {
      store->create_layer(*untouched);
      store->mark_complete(layer);
    }
  } catch (const std::exception& e) {
    spdlog::warn("{}: could not undo the failed ingest of layer {}: {}", path, layer, e.what());
  }
}

// An ingest into an existing layer adds its part to the layer: where the sources have no data,
// a tile they touch keeps the samples stored there (an earlier ingest's sources' part of the
// tile), as a source later in one ingest fills only the nodata of those before it. (The whole tile
// was replaced: a strip of nodata along the edge of the sources inside the tile.)
void keep_stored_samples(const Store& store, const std::string& layer, CellId cell,
                         const double* nodata, Tile<float>& tile) {
  const std::optional<RawTile> stored = store.get_tile(layer, cell);
  if (!stored) return;
  const Tile<float> before = to_tile<float>(*stored, nodata);
  const std::span<const float> was = before.data();
  const std::span<float> now = tile.data();
  for (size_t i = 0; i < now.size() && i < was.size(); ++i)
    if (std::isnan(now[i])) now[i] = was[i];
}

// An ingest into an existing layer adds its footprint to the layer's (core/data_footprint.h); a
// layer ingested before footprints were recorded gets none, since where its earlier sources lie
// is not known.
LayerInfo with_earlier_footprint(LayerInfo layer, const std::optional<LayerInfo>& existing) {
  if (!existing) return layer;
  const auto earlier = DataFootprint::from_provenance(existing->provenance, layer.name);
  const auto now = DataFootprint::from_provenance(layer.provenance, layer.name);
  if (earlier && now)
    layer.provenance["footprint"] = earlier->united(*now).to_json();
  else
    layer.provenance.erase("footprint");
  return layer;
}

}  // namespace

RasterIngestReport ingest_raster(const std::string& store_path,
                                 const std::vector<std::string>& sources,
                                 const RasterIngestOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const auto seconds = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // A new store is created while the ingest is planned (its schema and fsync overlap the
  // planning) and filled in bulk (Store::Mode::CreateBulk: each page written once, not through
  // the WAL); if the planning refuses the job, a store this process created is removed again,
  // so that a refused ingest leaves no store behind, as an existing store is left untouched (one
  // another process created meanwhile included: Store::created).
  Store::check_writable(store_path);  // before the planning, whose size checks read free space
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(store_path, ec) && !ec;
  std::future<std::unique_ptr<Store>> created;
  if (fresh)
    created = std::async(std::launch::async,
                         [&] { return Store::open(store_path, Store::Mode::CreateBulk); });
  std::optional<RasterIngestPlan> planned;
  try {
    planned = plan_raster_ingest(store_path, sources, o);
  } catch (...) {
    if (fresh) {
      try {
        remove_if_created(created.get());
      } catch (...) {  // not created: nothing to remove; the planning's error is the one to tell
      }
    }
    throw;
  }
  const RasterIngestPlan& plan = *planned;
  spdlog::debug("ingest {}: planned in {:.3f} s", o.layer, seconds());
  const LayerInfo& layer = plan.layer;
  RasterIngestReport report;
  report.level = layer.level;
  report.cells = int64_t(plan.cells.size());
  report.resampling = plan.resampling;

  auto store = fresh ? created.get() : Store::open(store_path, Store::Mode::Create);
  const std::optional<LayerInfo> existing = store->layer(layer.name);
  const bool new_layer = !existing;
  const bool was_complete = existing && !store->incomplete(layer.name);
  try {  // a definition the store refuses (a bad layer name) leaves no new store either
    store->create_layer(with_earlier_footprint(layer, existing));
  } catch (...) {
    if (store->created()) remove_if_created(std::move(store));
    throw;
  }
  std::vector<CellId> todo = plan.cells;
  int64_t run = 0;
  if (o.resume) {
    if (const auto previous = store->latest_unfinished_run(plan.run)) {
      run = *previous;
      report.resumed = true;
      const std::vector<CellId> done = store->done_cells(run, 0);
      std::erase_if(todo,
                    [&](CellId c) { return std::binary_search(done.begin(), done.end(), c); });
      report.skipped = report.cells - int64_t(todo.size());
    }
  }
  if (!report.resumed) run = store->begin_run(plan.run);
  // Readers refuse the layer until finish_run(run, "ok") (a killed ingest leaves it marked).
  store->mark_incomplete(layer.name, run);
  spdlog::debug("ingest {}: store ready at {:.3f} s", o.layer, seconds());
  spdlog::info(
      "ingest {}: {} cells at level {} ({:.3g} m pixels, sources {:.3g} m, up to {:.3g} "
      "MiB), {}{}",
      layer.name, report.cells, layer.level, plan.target_pixel_m, plan.source_pixel_m,
      double(plan.estimate_bytes) / (1 << 20), resampling_name(plan.resampling),
      report.resumed ? ", resuming run " + std::to_string(run) : "");

  const double* nodata = layer.nodata ? &*layer.nodata : nullptr;
  const bool categorical = layer.semantics == Semantics::Categorical;
  // Per thread: its resampler (GDAL handles, PROJ transforms) and work tiles, kept across cells.
  struct Worker {
    std::unique_ptr<TileResampler> resampler;
    Tile<float> tile;
    RawTile raw;
  };
  tbb::enumerable_thread_specific<Worker> workers;
  std::atomic<int64_t> written = 0, empty = 0, committed = 0;  // committed: batches
  std::atomic<bool> failed = false;
  std::exception_ptr error;
  std::mutex error_mutex;
  {
    Progress progress("ingest " + layer.name, int64_t(todo.size()), o.quiet);
    const std::vector<size_t> batches = sibling_batches(todo);
    const std::vector<size_t> order = largest_first(batches);
    std::atomic<size_t> next = 0;  // into `order`
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    const auto write_batch = [&](size_t chunk) {
      try {
        auto& [resampler, tile, raw] = workers.local();
        if (!resampler)
          resampler = std::make_unique<TileResampler>(default_grid(), plan.sources, plan.resampling,
                                                      categorical);
        Store::Batch batch(*store);
        const size_t begin = batches[chunk], end = batches[chunk + 1];
        for (size_t i = begin; i < end; ++i) {
          if (resampler->make(todo[i], layer.tile_size, tile)) {
            if (!new_layer) keep_stored_samples(*store, layer.name, todo[i], nodata, tile);
            to_raw(tile, layer.dtype, nodata, raw);
            batch.put_tile(layer.name, todo[i], raw);
            ++written;
          } else {
            ++empty;
          }
          batch.mark_done(run, 0, todo[i]);
        }
        // The batch holds every cell of this parent the ingest writes: fewer than four
        // children (the footprint's edge) still give the overview here, in parallel.
        if (layer.level > 0) batch.put_parent_overview(layer.name, todo[begin].parent());
        batch.commit();
        ++committed;
        progress.advance(int64_t(end - begin));
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!failed.exchange(true)) error = std::current_exception();
      }
    };
    arena.execute([&] {
      tbb::parallel_for(
          0, arena.max_concurrency(),
          [&](int) {
            for (size_t k; !failed && (k = next++) < order.size();) write_batch(order[k]);
          },
          tbb::simple_partitioner());
    });
  }
  if (!error && written == 0 && report.skipped == 0)  // a layer without a tile, never wanted
    error = std::make_exception_ptr(Error(fmt::format(
        "ingest {}: no tile written: no pixel of the {} cells at level {} ({:.3g} m pixels) has a "
        "valid sample of the sources ({:.3g} m pixels); {}",
        layer.name, report.cells, layer.level, plan.target_pixel_m, plan.source_pixel_m,
        new_layer ? "are they all nodata, or smaller than a pixel there (a finer --level)?"
                  : "the layer is as it was")));
  if (error) {
    std::string what = "unknown error";
    try {
      std::rethrow_exception(error);
    } catch (const std::exception& e) {
      what = e.what();
    }
    store->finish_run(run, "failed: " + what);
    // A layer given no tile is as it was (its overviews are made from the same stored tiles).
    const bool untouched = was_complete && (committed == 0 || written == 0) && !report.resumed;
    undo_failed_ingest(std::move(store), layer.name, run, new_layer,
                       untouched ? existing : std::nullopt);
    std::rethrow_exception(error);
  }
  spdlog::debug("ingest {}: tiles done at {:.3f} s", layer.name, seconds());
  store->update_overviews(layer.name);
  store->finish_run(run, "ok");
  spdlog::debug("ingest {}: overviews done at {:.3f} s", layer.name, seconds());
  report.written = written;
  report.empty = empty;
  report.seconds = seconds();
  return report;
}

}  // namespace maquette
