/* Mesa's OSMesa (software OpenGL, llvmpipe) drawing the mesh render_benchmark --write-mesh wrote
 * (its header there), into an off-screen RGBA buffer with a 32-bit depth buffer of the same size,
 * through the same pinhole (a frustum from the focal length, near 1 m): the side-by-side baseline
 * of our rasterizer (osmesa_side_by_side.sh). The mesh is uploaded once (vertex and index buffer
 * objects); each frame clears, draws every triangle with depth testing, and waits for the end
 * (glFinish). Prints the wall time and the process's CPU time (all threads) per frame in
 * milliseconds, each the least of FRAMES (default 5, after one warm-up frame), and the number of
 * pixels drawn, as "osmesa_ms=T cpu_ms=C drawn=N".
 * Usage: osmesa_render MESH [FRAMES]. Threads: LP_NUM_THREADS (llvmpipe's own variable; 0
 * rasterizes in the calling thread). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now_ms(clockid_t clock) {
  struct timespec t;
  clock_gettime(clock, &t);
  return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static void *read_block(FILE *f, size_t bytes, const char *what) {
  void *p = malloc(bytes);
  if (!p || fread(p, 1, bytes, f) != bytes) {
    fprintf(stderr, "osmesa_render: cannot read the mesh's %s\n", what);
    exit(1);
  }
  return p;
}

int main(int argc, char **argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: osmesa_render MESH [FRAMES]\n");
    return 2;
  }
  const int frames = argc > 2 ? atoi(argv[2]) : 5;
  FILE *f = fopen(argv[1], "rb");
  if (!f) {
    fprintf(stderr, "osmesa_render: cannot open %s\n", argv[1]);
    return 1;
  }
  int32_t header[4];
  double focal;
  if (fread(header, sizeof header, 1, f) != 1 || fread(&focal, sizeof focal, 1, f) != 1) {
    fprintf(stderr, "osmesa_render: %s has no header\n", argv[1]);
    return 1;
  }
  const int width = header[0], height = header[1];
  const size_t vertices = (size_t)header[2], triangles = (size_t)header[3];
  float *xyz = read_block(f, vertices * 3 * sizeof(float), "vertices");
  uint32_t *indices = read_block(f, triangles * 3 * sizeof(uint32_t), "triangles");
  fclose(f);
  /* The camera frame (x right, y down, z forward) to OpenGL's eye frame (y up, z backward). */
  for (size_t i = 0; i < vertices; ++i) {
    xyz[3 * i + 1] = -xyz[3 * i + 1];
    xyz[3 * i + 2] = -xyz[3 * i + 2];
  }

  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 32, 0, 0, NULL);
  void *buffer = malloc((size_t)width * (size_t)height * 4);
  if (!ctx || !buffer || !OSMesaMakeCurrent(ctx, buffer, GL_UNSIGNED_BYTE, width, height)) {
    fprintf(stderr, "osmesa_render: no OSMesa context\n");
    return 1;
  }
  glViewport(0, 0, width, height);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const double near = 1, far = 1e6;
  glFrustum(-width / 2.0 / focal * near, width / 2.0 / focal * near, -height / 2.0 / focal * near,
            height / 2.0 / focal * near, near, far);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glClearColor(0, 0, 0, 0);
  glColor3f(0.8f, 0.7f, 0.6f);

  GLuint objects[2];
  glGenBuffers(2, objects);
  glBindBuffer(GL_ARRAY_BUFFER, objects[0]);
  glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(vertices * 3 * sizeof(float)), xyz, GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, objects[1]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(triangles * 3 * sizeof(uint32_t)), indices,
               GL_STATIC_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, 0);

  double best = 1e30, best_cpu = 1e30;
  for (int k = 0; k <= frames; ++k) {
    const double t0 = now_ms(CLOCK_MONOTONIC), c0 = now_ms(CLOCK_PROCESS_CPUTIME_ID);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, (GLsizei)(triangles * 3), GL_UNSIGNED_INT, 0);
    glFinish();
    const double t = now_ms(CLOCK_MONOTONIC) - t0, c = now_ms(CLOCK_PROCESS_CPUTIME_ID) - c0;
    if (k > 0 && t < best) best = t; /* frame 0 warms up */
    if (k > 0 && c < best_cpu) best_cpu = c;
  }
  size_t drawn = 0;
  const uint8_t *rgba = buffer;
  for (size_t i = 0; i < (size_t)width * (size_t)height; ++i) drawn += rgba[4 * i + 3] != 0;
  printf("osmesa_ms=%.1f cpu_ms=%.1f drawn=%zu\n", best, best_cpu, drawn);
  OSMesaDestroyContext(ctx);
  return 0;
}
