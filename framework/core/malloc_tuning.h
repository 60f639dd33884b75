// Allocator settings for programs that make and free tile-sized buffers per cell.
#pragma once

namespace maquette {

// Tiles and planes are 64 KiB to 64 MiB buffers made and freed per cell: keeps glibc from
// mapping each one afresh and handing it back to the kernel (measured: half the page faults of
// an ingest, and a fifth of texture.procedural's time). Call once, at the start of main.
void keep_tile_buffers_mapped();

}  // namespace maquette
