//! Option values: their ranges, checked once for every front end, and their text forms
//! (`800x600`, `1,2,3`, `#rrggbb`) as the command and scene files write them. Each
//! function returns the message a user sees.

use crate::options::Background;

/// A picture size: 1 to 65536 pixels per side.
pub fn size(w: u32, h: u32) -> Result<(u32, u32), String> {
    if w == 0 || h == 0 || w > 65536 || h > 65536 {
        return Err(format!("size `{w}x{h}` out of range (1 to 65536 per side)"));
    }
    Ok((w, h))
}

/// A vertical field of view: strictly between 0 and 180 degrees.
pub fn fov(f: f64) -> Result<f64, String> {
    if !(f > 0.0 && f < 180.0) {
        return Err(format!("field of view `{f}` is outside (0, 180) degrees"));
    }
    Ok(f)
}

/// A distance (near and far planes, an orthographic height): finite and positive.
pub fn distance(v: f64) -> Result<f64, String> {
    if !(v.is_finite() && v > 0.0) {
        return Err(format!("distance `{v}` must be a positive number"));
    }
    Ok(v)
}

/// A shadow-map depth bias: 0 to 1.
pub fn bias(v: f64) -> Result<f64, String> {
    if !(v.is_finite() && (0.0..=1.0).contains(&v)) {
        return Err(format!("shadow bias `{v}` must be 0 to 1"));
    }
    Ok(v)
}

/// A shading tolerance per colour channel: above 0, at most 1.
pub fn tolerance(v: f64) -> Result<f64, String> {
    if !(v > 0.0 && v <= 1.0) {
        return Err(format!(
            "shading tolerance `{v}` must be above 0 and at most 1"
        ));
    }
    Ok(v)
}

/// Samples per pixel of the page image textured faces are drawn from: 0 to 16.
pub fn texture_samples(v: f64) -> Result<f64, String> {
    if !(0.0..=16.0).contains(&v) {
        return Err(format!(
            "texture samples `{v}` must be between 0 and 16 per pixel"
        ));
    }
    Ok(v)
}

/// A seam width in pixels: 0 to 10.
pub fn seams(v: f64) -> Result<f64, String> {
    if !(0.0..=10.0).contains(&v) {
        return Err(format!("seam width `{v}` must be between 0 and 10 pixels"));
    }
    Ok(v)
}

/// A crease angle: 0 to 180 degrees.
pub fn crease(v: f64) -> Result<f64, String> {
    if v.is_finite() && (0.0..=180.0).contains(&v) {
        Ok(v)
    } else {
        Err("the crease angle must be 0 to 180 degrees".into())
    }
}

/// A shadow-map size: 1 to 16384.
pub fn shadow_map_size(n: u32) -> Result<u32, String> {
    if !(1..=16384).contains(&n) {
        return Err(format!("shadow-map size `{n}` must be 1 to 16384"));
    }
    Ok(n)
}

/// A point or direction: three finite numbers.
pub fn vec3(v: [f64; 3]) -> Result<[f64; 3], String> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(format!("`{x}` is not finite")),
        None => Ok(v),
    }
}

/// A colour: three channels between 0 and 1.
pub fn colour(v: [f64; 3]) -> Result<[f64; 3], String> {
    if v.iter().any(|c| !(0.0..=1.0).contains(c)) {
        return Err(format!(
            "colour channels in `{},{},{}` must be between 0 and 1",
            v[0], v[1], v[2]
        ));
    }
    Ok(v)
}

/// A number written in `s`.
fn number(s: &str) -> Result<f64, String> {
    s.trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))
}

/// `WIDTHxHEIGHT`.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("expected WIDTHxHEIGHT, got `{s}`"))?;
    let w: u32 = w
        .trim()
        .parse()
        .map_err(|_| format!("bad width in `{s}`"))?;
    let h: u32 = h
        .trim()
        .parse()
        .map_err(|_| format!("bad height in `{s}`"))?;
    size(w, h).map_err(|_| format!("size `{s}` out of range (1 to 65536 per side)"))
}

/// A field of view in degrees.
pub fn parse_fov(s: &str) -> Result<f64, String> {
    fov(number(s)?).map_err(|_| format!("field of view `{s}` is outside (0, 180) degrees"))
}

/// A distance.
pub fn parse_distance(s: &str) -> Result<f64, String> {
    distance(number(s)?).map_err(|_| format!("distance `{s}` must be a positive number"))
}

/// A shadow bias.
pub fn parse_bias(s: &str) -> Result<f64, String> {
    bias(number(s)?).map_err(|_| format!("shadow bias `{s}` must be 0 to 1"))
}

/// A shading tolerance.
pub fn parse_tolerance(s: &str) -> Result<f64, String> {
    tolerance(number(s)?)
        .map_err(|_| format!("shading tolerance `{s}` must be above 0 and at most 1"))
}

/// A seam width.
pub fn parse_seams(s: &str) -> Result<f64, String> {
    seams(number(s)?).map_err(|_| format!("seam width `{s}` must be between 0 and 10 pixels"))
}

/// Samples per pixel of the page image textured faces are drawn from.
pub fn parse_texture_samples(s: &str) -> Result<f64, String> {
    texture_samples(number(s)?)
        .map_err(|_| format!("texture samples `{s}` must be between 0 and 16 per pixel"))
}

/// A crease angle.
pub fn parse_crease(s: &str) -> Result<f64, String> {
    let v: f64 = s.parse().map_err(|e| format!("{e}"))?;
    crease(v)
}

/// `X,Y,Z`.
pub fn parse_vec3(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').collect();
    if parts.len() != 3 {
        return Err(format!("expected X,Y,Z, got `{s}`"));
    }
    let mut v = [0.0; 3];
    for (o, p) in v.iter_mut().zip(parts) {
        let x: f64 = p
            .trim()
            .parse()
            .map_err(|_| format!("`{p}` is not a number"))?;
        if !x.is_finite() {
            return Err(format!("`{p}` is not finite"));
        }
        *o = x;
    }
    Ok(v)
}

/// `none`, `#rrggbb` or `R,G,B` (channels 0 to 1).
pub fn parse_background(s: &str) -> Result<Background, String> {
    let t = s.trim();
    if t.eq_ignore_ascii_case("none") {
        return Ok(Background::None);
    }
    if let Some(h) = t.strip_prefix('#') {
        let ch = |i: usize| h.get(i..i + 2).and_then(|c| u8::from_str_radix(c, 16).ok());
        return match (h.len(), ch(0), ch(2), ch(4)) {
            (6, Some(r), Some(g), Some(b)) => {
                Ok(Background::Colour([r, g, b].map(|v| v as f64 / 255.0)))
            }
            _ => Err(format!("`{s}` is not a #rrggbb colour")),
        };
    }
    let v = parse_vec3(t).map_err(|_| format!("`{s}` is not #rrggbb, R,G,B or none"))?;
    colour(v).map_err(|_| format!("colour channels in `{s}` must be between 0 and 1"))?;
    Ok(Background::Colour(v))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vectors_and_sizes_parse() {
        assert_eq!(parse_vec3("-1,2.5,3e2"), Ok([-1.0, 2.5, 300.0]));
        assert!(parse_vec3("1,2").is_err());
        assert!(parse_vec3("1,nan,2").is_err());
        assert_eq!(parse_size("800x600"), Ok((800, 600)));
        assert!(parse_size("0x600").is_err());
        assert!(parse_size("800").is_err());
        assert_eq!(parse_fov("30"), Ok(30.0));
        for bad in ["0", "180", "-5", "nan", "inf", "wide"] {
            assert!(parse_fov(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn ranges_name_the_value() {
        assert_eq!(
            seams(11.0).unwrap_err(),
            "seam width `11` must be between 0 and 10 pixels"
        );
        assert!(tolerance(0.0).is_err() && tolerance(1.0).is_ok());
        assert!(distance(f64::INFINITY).is_err() && distance(1e-9).is_ok());
        assert!(bias(-0.1).is_err() && bias(0.0).is_ok());
        assert!(crease(181.0).is_err() && crease(0.0).is_ok());
        assert!(colour([0.0, 1.0, 1.1]).is_err());
        assert_eq!(
            parse_background("#ff0000"),
            Ok(Background::Colour([1.0, 0.0, 0.0]))
        );
        assert_eq!(parse_background("None"), Ok(Background::None));
        assert!(parse_background("2,0,0").is_err());
    }
}
