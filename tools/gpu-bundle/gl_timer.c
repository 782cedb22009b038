/* LD_PRELOAD shim for is-egl: wall time spent inside a few OpenGL calls, per process, printed at exit.
 * clothbench loads every GL function through eglGetProcAddress (collide_is/src/gl_api.hpp), so this library
 * interposes eglGetProcAddress and hands out timing wrappers for the calls below. OpenGL queues drawing and
 * uploads; glReadPixels into client memory waits for them, so its time is the GPU's drawing plus the transfer
 * to the CPU: the read-back. No source change: LD_PRELOAD=libcb_gl_timer.so clothbench ...
 * GL_TIMER_LOG=FILE appends the summary there (default stderr). One "frame" = one glDrawBuffers call (the
 * OpenGL map renderer calls it once per render of all maps). Build: cc -O2 -shared -fPIC -o X.so gl_timer.c -ldl */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef unsigned int GLenum;
typedef int GLint;
typedef int GLsizei;
typedef void (*proc_t)(void);

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return 1e3 * (double)t.tv_sec + 1e-6 * (double)t.tv_nsec;
}

enum { READ, TEXIMAGE, BUFFERDATA, DRAW, CLEAR, DRAWBUFFERS, N };
static const char* const names[N] = {"glReadPixels", "glTexImage2D", "glBufferData", "glDrawElements", "glClear",
                                     "glDrawBuffers"};
static double total_ms[N];
static long calls[N];
static double read_bytes;
static proc_t real[N];

static int bytes_per_pixel(GLenum format, GLenum type) {
  const int channels = format == 0x1908 /* GL_RGBA */ ? 4 : 1;
  const int size = type == 0x1401 /* GL_UNSIGNED_BYTE */ ? 1 : 4;
  return channels * size;
}

#define TIMED(k, call)            \
  do {                            \
    const double t0 = now_ms();   \
    call;                         \
    total_ms[k] += now_ms() - t0; \
    ++calls[k];                   \
  } while (0)

static void w_read(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* data) {
  TIMED(READ, ((void (*)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*))real[READ])(x, y, w, h, format, type, data));
  read_bytes += (double)w * h * bytes_per_pixel(format, type);
}
static void w_teximage(GLenum a, GLint b, GLint c, GLsizei d, GLsizei e, GLint f, GLenum g, GLenum h, const void* i) {
  TIMED(TEXIMAGE, ((void (*)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*))real[TEXIMAGE])(
                      a, b, c, d, e, f, g, h, i));
}
static void w_bufferdata(GLenum a, intptr_t b, const void* c, GLenum d) {
  TIMED(BUFFERDATA, ((void (*)(GLenum, intptr_t, const void*, GLenum))real[BUFFERDATA])(a, b, c, d));
}
static void w_draw(GLenum a, GLsizei b, GLenum c, const void* d) {
  TIMED(DRAW, ((void (*)(GLenum, GLsizei, GLenum, const void*))real[DRAW])(a, b, c, d));
}
static void w_clear(unsigned int a) { TIMED(CLEAR, ((void (*)(unsigned int))real[CLEAR])(a)); }
static void w_drawbuffers(GLsizei a, const GLenum* b) {
  TIMED(DRAWBUFFERS, ((void (*)(GLsizei, const GLenum*))real[DRAWBUFFERS])(a, b));
}
static const proc_t wrappers[N] = {(proc_t)w_read, (proc_t)w_teximage, (proc_t)w_bufferdata, (proc_t)w_draw,
                                   (proc_t)w_clear, (proc_t)w_drawbuffers};

proc_t eglGetProcAddress(const char* name) {
  static proc_t (*next)(const char*);
  if (!next) next = (proc_t(*)(const char*))dlsym(RTLD_NEXT, "eglGetProcAddress");
  proc_t p = next ? next(name) : NULL;
  for (int k = 0; p && k < N; ++k)
    if (strcmp(name, names[k]) == 0) {
      real[k] = p;
      return wrappers[k];
    }
  return p;
}

__attribute__((destructor)) static void report(void) {
  const long frames = calls[DRAWBUFFERS];
  if (!frames) return;
  const char* path = getenv("GL_TIMER_LOG");
  FILE* f = path ? fopen(path, "a") : NULL;
  FILE* out = f ? f : stderr;
  fprintf(out, "{\"label\": \"%s\", \"frames\": %ld, \"read_bytes_per_frame\": %.0f", getenv("GL_TIMER_LABEL") ? getenv("GL_TIMER_LABEL") : "",
          frames, read_bytes / (double)frames);
  for (int k = 0; k < N; ++k)
    fprintf(out, ", \"%s\": {\"calls_per_frame\": %.2f, \"ms_per_frame\": %.4f}", names[k], (double)calls[k] / (double)frames,
            total_ms[k] / (double)frames);
  fprintf(out, "}\n");
  if (f) fclose(f);
}
