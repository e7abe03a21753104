//! The library example of README.md, kept compiling and working.

use std::path::Path;

use limn_depthsort::{order, OrderOptions};
use limn_paint::{painter_for, picture, Format, Style};
use limn_scene::Camera;

fn readme_example(dir: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let input = dir.join("bunny.obj");
    let scene = limn_load::load(&input, &Default::default())?;
    let camera = Camera::framing(&scene, 800, 600)?;
    let ordered = order(&scene, &camera, &OrderOptions::default())?; // exact by default
    let pic = picture(&scene, &ordered, &Style::default());
    let mut out = std::fs::File::create(dir.join("bunny.svg"))?;
    painter_for(Format::Svg).paint(&pic, &mut out)?;
    Ok(())
}

#[test]
fn the_readme_library_example_writes_an_svg() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bunny.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .unwrap();
    readme_example(dir.path()).unwrap();
    let svg = std::fs::read_to_string(dir.path().join("bunny.svg")).unwrap();
    assert!(svg.contains("<path") && svg.trim_end().ends_with("</svg>"));
}
