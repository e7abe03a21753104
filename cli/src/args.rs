//! Command-line arguments.

use std::path::PathBuf;

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::error::ErrorKind;
use clap::{Args, CommandFactory, Parser, Subcommand, ValueEnum};
use limn::values::{
    parse_background, parse_bias, parse_crease, parse_distance, parse_fov, parse_seams, parse_size,
    parse_texture_samples, parse_tolerance, parse_vec3,
};
use limn::{
    Against, Arith, Background, CheckOptions, CullMode, Format, Look, Method, RenderOptions,
    Shading, SortMode, ViewOptions,
};

/// Draw 3D polygon scenes as resolution-independent pictures with hidden surfaces
/// removed exactly.
#[derive(Debug, Parser)]
#[command(name = "limn", version, about, long_about = None, after_help = MAIN_HELP)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
    /// Worker threads for ordering (the output is the same for every count)
    /// [default: one per core]
    #[arg(long, global = true, value_name = "N", value_parser = clap::value_parser!(u16).range(1..))]
    pub threads: Option<u16>,
}

impl Cli {
    /// Checks combinations of flags that the parser cannot express: two outputs sent to
    /// standard output at once would be mixed into one stream.
    pub fn check_conflicts(&self) -> Result<(), clap::Error> {
        let dash = |p: &Option<PathBuf>| p.as_deref().is_some_and(|p| p.as_os_str() == "-");
        let clash = match &self.command {
            Command::Render(r) => dash(&r.output) && dash(&r.view.stats),
            Command::Demo(d) => dash(&d.output) && dash(&d.stats),
            // Without --stats the report itself goes to standard output.
            Command::Check(c) => dash(&c.diff) && (c.view.stats.is_none() || dash(&c.view.stats)),
        };
        if clash {
            return Err(Cli::command().error(
                ErrorKind::ArgumentConflict,
                "only one of the outputs can be `-` (standard output)",
            ));
        }
        if let Command::Render(r) = &self.command {
            // The raster methods neither order fragments nor stroke model edges.
            if r.method != MethodArg::Painter && (r.view.stats.is_some() || r.outline) {
                return Err(Cli::command().error(
                    ErrorKind::ArgumentConflict,
                    "--stats and --outline apply to the painter only, not to --method",
                ));
            }
        }
        Ok(())
    }
}

/// Exit statuses, shown under every help text.
const EXIT_CODES: &str = "Exit status: 0 done (warnings go to standard error), 1 error (bad \
input, refused output, limit reached; no output file is left), 2 usage error, 3 `check` \
found pixels that disagree with the reference.";

const MAIN_HELP: &str = "Examples:
  limn demo                              # the built-in scene to demo.svg
  limn render bunny.obj -o bunny.pdf     # any mesh or scene file, framed automatically
  limn check bunny.obj --against raycast # the painter's picture against ray casting
  limn render big.obj --threads 1        # on one core (the same output as on all)

Exit status: 0 done (warnings go to standard error), 1 error (bad input, refused output, \
limit reached; no output file is left), 2 usage error, 3 `check` found pixels that \
disagree with the reference.";

const RENDER_HELP: &str = "Examples:
  limn render scene.obj                          # scene.svg beside the input
  limn render scene.toml -o fig.pdf --size 1200x900
  limn render mesh.stl -o m.svg --eye 3,2,5 --target 0,0,0 --fov 30 --outline
  limn render part.stl -o plan.svg --eye 0,10,0 --up 0,0,-1 --ortho 4   # a plan view
  limn render soup.obj -o s.png --method raycast # an image-space picture
  limn render scene.obj -o fig.tikz              # \\input{fig.tikz} in a LaTeX document
  limn render scene.obj -o fig.tex --format tikz --standalone   # pdflatex fig.tex
  limn render part.stl -o p.svg --style hidden-line --hidden dashed
  limn render part.stl -o p.svg --style hidden-line --fill none --crease 20  # plotter lines
  limn render plot.toml -o plot.pdf              # [[line]], [[points]], [[label]] hidden exactly
  limn render bunny.obj -o b.pdf --shading phong --shading-tolerance 0.002
  limn render crate.obj -o c.svg                 # vt + map_Kd (PNG/JPEG): each image embedded once
  limn render shadows.toml -o s.svg              # [[light]] shadows = true: exact shadows
  limn render shadows.toml -o s.png --method zbuffer --shadow-bias 0.002  # shadow maps

Exit status: 0 done (warnings go to standard error), 1 error (bad input, refused output, \
limit reached; no output file is left), 2 usage error.";

const CHECK_HELP: &str = "Examples:
  limn check scene.obj                            # against exact ray casting
  limn check scene.obj --against raycast --diff d.png --stats report.json

Exit status: 0 the pictures agree outside the edge band, 1 error, 2 usage error, 3 pixels \
disagree (the report says where).";

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Render a scene file (OBJ, STL, PLY, glTF/GLB, or a TOML scene) to SVG, PDF, EPS, TikZ or
    /// PNG.
    #[command(after_help = RENDER_HELP)]
    Render(RenderArgs),
    /// Render the built-in demo scene (a cyclic overlap, two interpenetrating boxes, a
    /// shaded sphere with a rod through it, exact shadows on a floor) to demo.svg or
    /// OUTPUT.
    #[command(after_help = EXIT_CODES)]
    Demo(DemoArgs),
    /// Compare the painter's result pixel by pixel with an image-space reference.
    #[command(after_help = CHECK_HELP)]
    Check(CheckArgs),
}

/// A parser for a library enum that names its values (`ALL`, `name`, `from_name`): the
/// command accepts exactly the library's names, with no second list to keep in step.
fn named<T: Copy + Send + Sync + 'static>(
    all: &'static [T],
    name: fn(T) -> &'static str,
    from_name: fn(&str) -> Option<T>,
) -> impl TypedValueParser<Value = T> {
    PossibleValuesParser::new(all.iter().map(|&v| name(v)))
        .try_map(move |s| from_name(&s).ok_or("not a name the library knows"))
}

fn sort_parser() -> impl TypedValueParser<Value = SortMode> {
    named(&SortMode::ALL, SortMode::name, SortMode::from_name)
}

fn arith_parser() -> impl TypedValueParser<Value = Arith> {
    named(&Arith::ALL, Arith::name, Arith::from_name)
}

fn cull_parser() -> impl TypedValueParser<Value = CullMode> {
    named(&CullMode::ALL, CullMode::name, CullMode::from_name)
}

fn shading_parser() -> impl TypedValueParser<Value = Shading> {
    named(&Shading::ALL, Shading::name, |s| s.parse().ok())
}

fn format_parser() -> impl TypedValueParser<Value = Format> {
    named(&Format::ALL, Format::name, Format::from_name)
}

/// Image-space methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MethodArg {
    /// Painter's order (vector; the default).
    Painter,
    /// Z-buffer.
    Zbuffer,
    /// Scan-line z-buffer.
    Scanline,
    /// A-buffer (transparency).
    Abuffer,
    /// Warnock area subdivision.
    Warnock,
    /// Exact ray casting at pixel centres.
    Raycast,
}

/// Camera and view flags shared by render and check.
#[derive(Debug, Clone, Args)]
pub struct ViewArgs {
    /// Picture size in pixels, WIDTHxHEIGHT [default: 800x600, or the scene file's].
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Eye position X,Y,Z [default: frame the scene from the right, above and in front].
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub eye: Option<[f64; 3]>,
    /// Point looked at [default: the centre of the scene's bounding box].
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub target: Option<[f64; 3]>,
    /// Up direction [default: 0,1,0].
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_vec3, allow_hyphen_values = true)]
    pub up: Option<[f64; 3]>,
    /// Vertical field of view in degrees [default: 45].
    #[arg(long, value_name = "DEG", value_parser = parse_fov, allow_negative_numbers = true)]
    pub fov: Option<f64>,
    /// Orthographic (parallel) projection showing HEIGHT world units vertically; without
    /// HEIGHT the scene is framed [default: perspective, or the scene file's
    /// `projection`].
    #[arg(long, value_name = "HEIGHT", num_args = 0..=1, value_parser = parse_distance)]
    pub ortho: Option<Option<f64>>,
    /// Visibility ordering: adaptive (exact pairwise order, splitting only cycles), bsp,
    /// newell, or simple (one depth per polygon, a baseline) [default: adaptive, or the
    /// scene file's].
    #[arg(long, value_parser = sort_parser())]
    pub sort: Option<SortMode>,
    /// Arithmetic of the geometric decisions: exact, or float (an epsilon, the
    /// baseline) [default: exact, or the scene file's].
    #[arg(long, value_parser = arith_parser())]
    pub arith: Option<Arith>,
    /// Back-face culling: auto (closed opaque objects and parts), on, off [default: auto, or the
    /// scene file's].
    #[arg(long, value_parser = cull_parser())]
    pub cull: Option<CullMode>,
    /// Distance of the near clipping plane from the eye; geometry closer than this is
    /// cut away (with a warning) [default: the scene file's, else just before the nearest
    /// corner of the scene's bounds, but at least far / 10⁴].
    #[arg(long, value_name = "DIST", value_parser = parse_distance, allow_negative_numbers = true)]
    pub near: Option<f64>,
    /// Distance of the far plane from the eye (only depth precision of image-space
    /// methods depends on it) [default: just beyond the farthest corner of the bounds].
    #[arg(long, value_name = "DIST", value_parser = parse_distance, allow_negative_numbers = true)]
    pub far: Option<f64>,
    /// Stop with an error (and no output) once ordering has made this many fragments
    /// (every polygon and every piece of every split counts) [default: 50 per face +
    /// 200,000].
    #[arg(long, value_name = "N")]
    pub max_fragments: Option<usize>,
    /// The visible map: split every face exactly along what hides it and leave the hidden
    /// parts out of the picture (each visible region drawn once; smaller files for
    /// assemblies and meshes seen with much hidden) [default: off, or the scene file's
    /// `visible`].
    #[arg(long)]
    pub visible: bool,
    /// Follow references (MTL, buffers, meshes) that lead outside the input's folder.
    #[arg(long)]
    pub allow_outside: bool,
    /// Write statistics as one JSON object to PATH (`-` = standard output).
    #[arg(long, value_name = "PATH|-")]
    pub stats: Option<PathBuf>,
    /// Interpolation across lit faces with vertex normals: flat, gouraud (colours at
    /// the vertices) or phong (lighting per point; image-space methods per pixel,
    /// vector outputs within --shading-tolerance) [default: the scene file's, else
    /// gouraud where there are vertex normals].
    #[arg(long, value_parser = shading_parser())]
    pub shading: Option<Shading>,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
}

/// `limn render`.
#[derive(Debug, Clone, Args)]
pub struct RenderArgs {
    /// The scene: .obj, .stl, .ply, .gltf, .glb or .toml.
    pub input: PathBuf,
    /// Output file (`-` = standard output) [default: INPUT with the format's extension].
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: Option<PathBuf>,
    /// Output format [default: from OUTPUT's extension, else svg].
    #[arg(long, value_parser = format_parser())]
    pub format: Option<Format>,
    /// Stroke the original model edges (never the cuts).
    #[arg(long)]
    pub outline: bool,
    /// Width in pixels of the seam flaps that close the hairlines viewers leave between
    /// adjacent faces: each opaque face is extended this far under the neighbours painted
    /// after it, which cover the flap, so the picture is unchanged (0 = none).
    #[arg(
        long,
        value_name = "PX",
        default_value_t = limn::DEFAULT_SEAMS,
        value_parser = parse_seams,
        allow_negative_numbers = true
    )]
    pub seams: f64,
    /// Background colour: #rrggbb, R,G,B in 0..1, or `none` (transparent) [default: the
    /// scene file's, else none].
    #[arg(long, value_name = "COLOUR", value_parser = parse_background)]
    pub background: Option<Background>,
    /// Largest difference per colour channel (0..1) between the painted picture and
    /// per-point shading where the format cannot interpolate exactly: Phong in every
    /// vector format, Gouraud in SVG [default: 1/255, one 8-bit step].
    #[arg(long, value_name = "T", default_value_t = 1.0 / 255.0, value_parser = parse_tolerance)]
    pub shading_tolerance: f64,
    /// SVG and PDF: opaque textured faces are drawn from one image of the page, sampled
    /// N times per pixel each way (their outlines stay exact; fewer samples on pages of
    /// over 4 million); 0 draws each face's texture under its own maps (resolution
    /// independent, but a clip per triangle for viewers).
    #[arg(long, value_name = "N", default_value_t = limn::DEFAULT_TEXTURE_SAMPLES, value_parser = parse_texture_samples)]
    pub texture_samples: f64,
    /// How to render: painter's order (vector) or an image-space method (PNG only).
    #[arg(long, value_enum, default_value_t = MethodArg::Painter)]
    pub method: MethodArg,
    /// Shadow maps of --method zbuffer, scanline and warnock (lights with `shadows =
    /// true`): samples per side of each map (a point light has six).
    #[arg(long, value_name = "N", default_value_t = 2048, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub shadow_map_size: u32,
    /// Shadow maps' depth bias, as a fraction of the scene's bounding-box diagonal: a
    /// point is shadowed only when farther from the light than the map's sample by more
    /// (too small: acne; too large: shadows detach). The painter and ray casting are
    /// exact and use none.
    #[arg(long, value_name = "B", default_value_t = 1e-3, value_parser = parse_bias)]
    pub shadow_bias: f64,
    /// TikZ output: wrap the picture in a complete LaTeX document (`standalone` class)
    /// that pdflatex compiles as it is, instead of a bare `tikzpicture` for `\input`.
    #[arg(long)]
    pub standalone: bool,
    /// Picture style: filled faces, or a hidden-line drawing (the mesh's silhouette,
    /// boundary and crease edges, exactly where visible) [default: the scene file's, else
    /// filled].
    #[arg(long, value_enum)]
    pub style: Option<StyleArg>,
    /// Hidden-line drawings: draw edges between faces meeting at more than DEG degrees
    /// [default: the scene file's, else 30].
    #[arg(long, value_name = "DEG", value_parser = parse_crease)]
    pub crease: Option<f64>,
    /// Hidden-line drawings: leave hidden edges out, or draw them dashed [default: the
    /// scene file's, else omit].
    #[arg(long, value_enum)]
    pub hidden: Option<HiddenArg>,
    /// Hidden-line drawings: fill faces with the background colour (white when there is
    /// none), or draw lines only, joined into the longest polylines (for plotters and
    /// cutters) [default: the scene file's, else background].
    #[arg(long, value_enum)]
    pub fill: Option<FillArg>,
    /// Camera, ordering and reporting flags.
    #[command(flatten)]
    pub view: ViewArgs,
}

/// Picture styles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StyleArg {
    /// Shaded faces (with lines, markers and labels over them).
    Filled,
    /// Silhouette, boundary and crease edges where visible.
    HiddenLine,
}

/// Hidden edges of hidden-line drawings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HiddenArg {
    /// Left out.
    Omit,
    /// Drawn dashed.
    Dashed,
}

/// Faces of hidden-line drawings.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FillArg {
    /// Filled with the background colour.
    Background,
    /// Not drawn: lines only.
    None,
}

/// `limn demo`.
#[derive(Debug, Clone, Args)]
pub struct DemoArgs {
    /// Output file [default: demo.svg]; the format follows the extension.
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: Option<PathBuf>,
    /// Stroke the original model edges.
    #[arg(long)]
    pub outline: bool,
    /// Write statistics as JSON to PATH (`-` = standard output).
    #[arg(long, value_name = "PATH|-")]
    pub stats: Option<PathBuf>,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
}

/// References for `limn check`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AgainstArg {
    /// Z-buffer with f64 depth.
    Zbuffer,
    /// Exact ray casting.
    Raycast,
    /// Warnock area subdivision.
    Warnock,
    /// Scan-line z-buffer.
    Scanline,
}

/// `limn check`.
#[derive(Debug, Clone, Args)]
pub struct CheckArgs {
    /// The scene: .obj, .stl, .ply, .gltf, .glb or .toml.
    pub input: PathBuf,
    /// The reference to compare with.
    #[arg(long, value_enum, default_value_t = AgainstArg::Raycast)]
    pub against: AgainstArg,
    /// Write an image with mismatching pixels marked (PNG).
    #[arg(long, value_name = "DIFF.png")]
    pub diff: Option<PathBuf>,
    /// Width in pixels of the seam flaps of the picture compared, as `render` draws it
    /// (0 = none). The flaps lie under later faces, so no width changes the result.
    #[arg(
        long,
        value_name = "PX",
        default_value_t = limn::DEFAULT_SEAMS,
        value_parser = parse_seams,
        allow_negative_numbers = true
    )]
    pub seams: f64,
    /// Camera, ordering and reporting flags.
    #[command(flatten)]
    pub view: ViewArgs,
}

impl MethodArg {
    /// The library's method.
    pub fn method(self) -> Method {
        match self {
            MethodArg::Painter => Method::Painter,
            MethodArg::Zbuffer => Method::ZBuffer,
            MethodArg::Scanline => Method::ScanLine,
            MethodArg::Abuffer => Method::ABuffer,
            MethodArg::Warnock => Method::Warnock,
            MethodArg::Raycast => Method::RayCast,
        }
    }
}

impl AgainstArg {
    /// The library's reference.
    pub fn against(self) -> Against {
        match self {
            AgainstArg::Zbuffer => Against::ZBuffer,
            AgainstArg::Raycast => Against::RayCast,
            AgainstArg::Warnock => Against::Warnock,
            AgainstArg::Scanline => Against::ScanLine,
        }
    }
}

impl ViewArgs {
    /// The library's view options.
    pub fn options(&self) -> ViewOptions {
        ViewOptions {
            size: self.size,
            eye: self.eye,
            target: self.target,
            up: self.up,
            fov: self.fov,
            ortho: self.ortho,
            sort: self.sort,
            arith: self.arith,
            cull: self.cull,
            near: self.near,
            far: self.far,
            max_fragments: self.max_fragments,
            allow_outside: self.allow_outside,
            shading: self.shading,
            matrix: None,
            visible: self.visible,
        }
    }
}

impl RenderArgs {
    /// The library's render options.
    pub fn options(&self) -> RenderOptions {
        RenderOptions {
            view: self.view.options(),
            format: self.format,
            outline: self.outline,
            seams: self.seams,
            background: self.background,
            shading_tolerance: self.shading_tolerance,
            texture_samples: self.texture_samples,
            method: self.method.method(),
            shadow_map_size: self.shadow_map_size,
            shadow_bias: self.shadow_bias,
            standalone: self.standalone,
            style: self.style.map(|s| match s {
                StyleArg::Filled => Look::Filled,
                StyleArg::HiddenLine => Look::HiddenLine,
            }),
            crease: self.crease,
            dashed: self.hidden.map(|h| h == HiddenArg::Dashed),
            fill: self.fill.map(|f| f == FillArg::Background),
            stats: self.view.stats.clone(),
        }
    }
}

impl CheckArgs {
    /// The library's check options.
    pub fn options(&self) -> CheckOptions {
        CheckOptions {
            view: self.view.options(),
            against: self.against.against(),
            diff: self.diff.clone(),
            seams: self.seams,
            stats: self.view.stats.clone(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ortho_takes_an_optional_height() {
        let r = |args: &[&str]| match Cli::try_parse_from(args).unwrap().command {
            Command::Render(r) => r.view.ortho,
            _ => unreachable!(),
        };
        assert_eq!(r(&["limn", "render", "a.obj"]), None);
        assert_eq!(r(&["limn", "render", "a.obj", "--ortho"]), Some(None));
        assert_eq!(
            r(&["limn", "render", "a.obj", "--ortho", "2.5"]),
            Some(Some(2.5))
        );
        assert!(Cli::try_parse_from(["limn", "render", "a.obj", "--ortho", "-1"]).is_err());
    }

    #[test]
    fn two_outputs_on_standard_output_conflict() {
        let parse = |a: &[&str]| Cli::try_parse_from(a).unwrap().check_conflicts();
        assert!(parse(&["limn", "render", "a.obj", "-o", "-", "--stats", "-"]).is_err());
        assert!(parse(&["limn", "render", "a.obj", "-o", "-", "--stats", "s.json"]).is_ok());
        assert!(parse(&["limn", "demo", "-o", "-", "--stats", "-"]).is_err());
        assert!(parse(&["limn", "check", "a.obj", "--diff", "-"]).is_err());
        assert!(parse(&["limn", "check", "a.obj", "--diff", "-", "--stats", "s"]).is_ok());
        assert!(parse(&[
            "limn",
            "render",
            "a.obj",
            "--method",
            "zbuffer",
            "--outline"
        ])
        .is_err());
        assert!(
            parse(&["limn", "render", "a.obj", "--method", "raycast", "--stats", "-"]).is_err()
        );
        assert!(parse(&[
            "limn",
            "render",
            "a.obj",
            "--method",
            "painter",
            "--outline"
        ])
        .is_ok());
    }

    #[test]
    fn leading_minus_is_a_value() {
        let cli = Cli::try_parse_from(["limn", "render", "a.obj", "--eye", "-1,2,3"]).unwrap();
        let Command::Render(r) = cli.command else {
            panic!("render expected")
        };
        assert_eq!(r.view.eye, Some([-1.0, 2.0, 3.0]));
        let cli = Cli::try_parse_from(["limn", "render", "a.obj", "--eye=-1,2,3"]).unwrap();
        let Command::Render(r) = cli.command else {
            panic!("render expected")
        };
        assert_eq!(r.view.eye, Some([-1.0, 2.0, 3.0]));
    }
}
