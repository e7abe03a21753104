/*
 * gl2ps_driver: draws a limn-projected scene with gl2ps (through an
 * offscreen OSMesa OpenGL context) and writes gl2ps's SVG.
 *
 * Build:  gcc -O2 -o gl2ps_driver gl2ps_driver.c -lgl2ps -lOSMesa -lm
 *         (Debian bookworm: libgl2ps-dev libosmesa6-dev; see install.sh)
 * Usage:  gl2ps_driver SORT IN.txt OUT.svg      SORT = bsp | simple
 *
 * IN.txt is the exchange format described in README.md:
 *     limn-projected 1
 *     W H
 *     N
 *     r g b k x1 y1 z1 ... xk yk zk          (N lines)
 * x is the pixel column (0 = left), y the pixel row (0 = top), z the
 * normalised depth in [-1, 1], smaller = nearer.
 *
 * How the scene reaches gl2ps:
 *   - glOrtho(0, W, H, 0, 2, -2): x -> window x unchanged; y flipped so
 *     that row 0 is the top of the window (gl2ps flips window y back when
 *     it writes SVG, so an input vertex (x, y) ends at SVG (x, y));
 *     z_ndc = z / 2, so window depth = (z/2 + 1)/2 grows with z: the
 *     smaller z is the nearer one, as OpenGL and gl2ps both expect.  The
 *     depth range is twice the exchange range so that a vertex at exactly
 *     z = +-1 (or a hair outside, after rounding) is never clipped.
 *   - each polygon is one GL_POLYGON with glColor3ub, no lighting, smooth
 *     shading (GL_FLAT would blacken the vertices clipping creates; all
 *     vertices carry the same colour, so every face stays flat), no
 *     culling, no lines drawn at all.
 *   - gl2psBeginPage(GL2PS_SVG, SORT, GL2PS_NO_PS3_SHADING | GL2PS_SILENT |
 *     GL2PS_USE_CURRENT_VIEWPORT | GL2PS_NO_BLENDING | GL2PS_NO_TEXT |
 *     GL2PS_NO_PIXMAP). GL2PS_DRAW_BACKGROUND is NOT set: the SVG has no
 *     background rectangle, uncovered pixels stay transparent.
 *     GL2PS_BEST_ROOT and GL2PS_OCCLUSION_CULL are not set (gl2ps's
 *     defaults; SORT "bsp-best" adds GL2PS_BEST_ROOT for experiments).
 *   - the usual loop: on GL2PS_OVERFLOW the feedback buffer is doubled and
 *     the page drawn again.
 *
 * Colours: glColor3ub; OpenGL feedback returns r/255 as a float and gl2ps
 * writes "#rrggbb" from (int)(255 * f).  check.sh verifies that every
 * value 0..255 comes back exact in each channel (it does with Mesa 22).
 *
 * Output: the SVG (gl2ps writes OUT.svg.tmp; it is copied to OUT.svg with
 * the root's width="Wpt" height="Hpt" rewritten as width="W" height="H",
 * nothing else changed), and on
 * stdout one line "primitives N": the number of <polygon> elements gl2ps
 * wrote (after BSP splitting and its fan triangulation of each polygon).
 * Any error: message on stderr, exit 1, no OUT.svg.
 */
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <gl2ps.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    unsigned char rgb[3];
    int k;
    double *xyz; /* 3k values */
} Poly;

static const char *g_tmp = NULL;

static void die(const char *fmt, const char *arg)
{
    fprintf(stderr, "gl2ps_driver: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n");
    if (g_tmp) remove(g_tmp);
    exit(1);
}

static Poly *read_scene(const char *path, int *W, int *H, long *N)
{
    FILE *f = fopen(path, "r");
    if (!f) die("cannot open %s", path);
    char magic[32];
    int version;
    if (fscanf(f, "%31s %d", magic, &version) != 2 || strcmp(magic, "limn-projected") != 0 || version != 1)
        die("%s: not a 'limn-projected 1' file", path);
    if (fscanf(f, "%d %d", W, H) != 2 || *W <= 0 || *H <= 0)
        die("%s: bad picture size", path);
    if (fscanf(f, "%ld", N) != 1 || *N < 0) die("%s: bad polygon count", path);
    Poly *polys = calloc((size_t)(*N ? *N : 1), sizeof(Poly));
    if (!polys) die("out of memory reading %s", path);
    for (long i = 0; i < *N; i++) {
        int r, g, b, k;
        if (fscanf(f, "%d %d %d %d", &r, &g, &b, &k) != 4)
            die("%s: truncated polygon line", path);
        if (r < 0 || r > 255 || g < 0 || g > 255 || b < 0 || b > 255 || k < 3)
            die("%s: bad colour or vertex count", path);
        polys[i].rgb[0] = (unsigned char)r;
        polys[i].rgb[1] = (unsigned char)g;
        polys[i].rgb[2] = (unsigned char)b;
        polys[i].k = k;
        polys[i].xyz = malloc(sizeof(double) * 3 * (size_t)k);
        if (!polys[i].xyz) die("out of memory reading %s", path);
        for (int j = 0; j < 3 * k; j++)
            if (fscanf(f, "%lf", &polys[i].xyz[j]) != 1)
                die("%s: truncated vertex list", path);
    }
    fclose(f);
    return polys;
}

static void draw(const Poly *polys, long n)
{
    for (long i = 0; i < n; i++) {
        const Poly *p = &polys[i];
        glColor3ub(p->rgb[0], p->rgb[1], p->rgb[2]);
        glBegin(GL_POLYGON);
        for (int j = 0; j < p->k; j++)
            glVertex3d(p->xyz[3 * j], p->xyz[3 * j + 1], p->xyz[3 * j + 2]);
        glEnd();
    }
}

/* Copies gl2ps's SVG from tmp to out, with the root element's
 * width="Wpt" height="Hpt" (gl2ps's units) rewritten as width="W"
 * height="H" (user units = pixels; the viewBox is already "0 0 W H").
 * Returns the number of <polygon elements. */
static long finish_svg(const char *tmp, const char *out, int W, int H)
{
    FILE *f = fopen(tmp, "rb");
    if (!f) die("cannot read back %s", tmp);
    size_t cap = 1 << 16, len = 0, got;
    char *buf = malloc(cap + 1);
    if (!buf) die("%s", "out of memory reading the SVG back");
    while ((got = fread(buf + len, 1, cap - len, f)) > 0) {
        len += got;
        if (len == cap) {
            cap *= 2;
            buf = realloc(buf, cap + 1);
            if (!buf) die("%s", "out of memory reading the SVG back");
        }
    }
    fclose(f);
    buf[len] = 0;

    char want[96], repl[96];
    snprintf(want, sizeof want, "width=\"%dpt\" height=\"%dpt\"", W, H);
    snprintf(repl, sizeof repl, "width=\"%d\" height=\"%d\"", W, H);
    char *at = strstr(buf, want);
    if (!at) die("%s", "gl2ps's SVG header is not the expected one (width/height in pt)");

    long n = 0;
    for (char *p = buf; (p = strstr(p, "<polygon")) != NULL; p += 8) n++;

    FILE *o = fopen(out, "wb");
    if (!o) die("cannot write %s", out);
    size_t pre = (size_t)(at - buf), wl = strlen(want);
    int ok = fwrite(buf, 1, pre, o) == pre && fputs(repl, o) >= 0 &&
             fwrite(at + wl, 1, len - pre - wl, o) == len - pre - wl;
    if (fclose(o) != 0 || !ok) { remove(out); die("cannot write %s", out); }
    free(buf);
    return n;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: gl2ps_driver bsp|simple IN.txt OUT.svg\n");
        return 1;
    }
    GLint sort, extra = 0;
    if (strcmp(argv[1], "bsp") == 0) sort = GL2PS_BSP_SORT;
    else if (strcmp(argv[1], "simple") == 0) sort = GL2PS_SIMPLE_SORT;
    else if (strcmp(argv[1], "bsp-best") == 0) { sort = GL2PS_BSP_SORT; extra = GL2PS_BEST_ROOT; }
    else die("unknown sort '%s' (bsp or simple)", argv[1]);

    int W, H;
    long N;
    Poly *polys = read_scene(argv[2], &W, &H, &N);

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx) die("%s", "OSMesaCreateContextExt failed");
    void *pixels = malloc((size_t)W * (size_t)H * 4);
    if (!pixels) die("%s", "out of memory for the offscreen buffer");
    if (!OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, W, H))
        die("%s", "OSMesaMakeCurrent failed (picture too large?)");

    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)W, (double)H, 0.0, 2.0, -2.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_LIGHTING);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDisable(GL_DITHER);
    glShadeModel(GL_SMOOTH); /* GL_FLAT gives black clip vertices in feedback */
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(1.0f, 1.0f, 1.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    size_t tmplen = strlen(argv[3]) + 8;
    char *tmp = malloc(tmplen);
    snprintf(tmp, tmplen, "%s.tmp", argv[3]);
    g_tmp = tmp;

    /* feedback buffer: GL_3D_COLOR gives 7 floats a vertex, 2 a polygon */
    double est = 4096.0;
    for (long i = 0; i < N; i++) est += 2.0 + 7.0 * polys[i].k;
    est *= 2.0;
    if (est > 1.0e9) est = 1.0e9;
    GLint bufsize = (GLint)est;
    GLint options = GL2PS_NO_PS3_SHADING | GL2PS_SILENT | GL2PS_USE_CURRENT_VIEWPORT |
                    GL2PS_NO_BLENDING | GL2PS_NO_TEXT | GL2PS_NO_PIXMAP | extra;
    GLint state = GL2PS_OVERFLOW;
    while (state == GL2PS_OVERFLOW) {
        FILE *out = fopen(tmp, "wb");
        if (!out) die("cannot write %s", tmp);
        GLint r = gl2psBeginPage("limn scene", "limn gl2ps_driver", NULL, GL2PS_SVG, sort,
                                 options, GL_RGBA, 0, NULL, 0, 0, 0, bufsize, out, argv[3]);
        if (r != GL2PS_SUCCESS) { fclose(out); die("%s", "gl2psBeginPage failed"); }
        draw(polys, N);
        state = gl2psEndPage();
        fclose(out);
        if (state == GL2PS_OVERFLOW) {
            if (bufsize > 1 << 29) die("%s", "feedback buffer would exceed 2^30 floats");
            bufsize *= 2;
        }
    }
    if (state == GL2PS_NO_FEEDBACK) {
        /* an empty picture: gl2ps still wrote a valid empty SVG */
    } else if (state != GL2PS_SUCCESS) {
        die("%s", "gl2psEndPage failed");
    }
    GLenum err = glGetError();
    if (err != GL_NO_ERROR) {
        char msg[32];
        snprintf(msg, sizeof msg, "0x%x", err);
        die("OpenGL error %s", msg);
    }
    long prims = finish_svg(tmp, argv[3], W, H);
    remove(tmp);
    g_tmp = NULL;
    printf("primitives %ld\n", prims);

    OSMesaDestroyContext(ctx);
    free(pixels);
    return 0;
}
