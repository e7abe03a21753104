//! Output file formats.

use std::fmt as stdfmt;

/// An output file format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// Scalable Vector Graphics.
    Svg,
    /// Portable Document Format, one page.
    Pdf,
    /// Encapsulated PostScript.
    Eps,
    /// Portable Network Graphics (a raster).
    Png,
    /// A TikZ picture for LaTeX (extensions `.tikz` and `.pgf`).
    Tikz,
}

impl Format {
    /// Every format, in a fixed order.
    pub const ALL: [Format; 5] = [
        Format::Svg,
        Format::Pdf,
        Format::Eps,
        Format::Png,
        Format::Tikz,
    ];

    /// The format of a file extension (`"svg"`, `".PDF"`, `"eps"`, `"ps"`, `"png"`, `"tikz"`,
    /// `"pgf"`; any case, with or without the dot).
    pub fn from_extension(ext: &str) -> Option<Format> {
        let ext = ext.strip_prefix('.').unwrap_or(ext);
        if ext.eq_ignore_ascii_case("ps") {
            return Some(Format::Eps);
        }
        if ext.eq_ignore_ascii_case("pgf") {
            return Some(Format::Tikz);
        }
        Format::from_name(ext)
    }

    /// The format called `name` (`"svg"`, `"pdf"`, `"eps"`, `"png"` or `"tikz"`, any case).
    pub fn from_name(name: &str) -> Option<Format> {
        Format::ALL
            .into_iter()
            .find(|f| f.name().eq_ignore_ascii_case(name))
    }

    /// The lower-case name, which is also the usual file extension.
    pub fn name(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Pdf => "pdf",
            Format::Eps => "eps",
            Format::Png => "png",
            Format::Tikz => "tikz",
        }
    }
}

impl stdfmt::Display for Format {
    fn fmt(&self, f: &mut stdfmt::Formatter<'_>) -> stdfmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn format_names_and_extensions() {
        assert_eq!(Format::from_extension(".SVG"), Some(Format::Svg));
        assert_eq!(Format::from_extension("ps"), Some(Format::Eps));
        assert_eq!(Format::from_extension("Png"), Some(Format::Png));
        assert_eq!(Format::from_extension("PGF"), Some(Format::Tikz));
        assert_eq!(Format::from_extension(".tikz"), Some(Format::Tikz));
        assert_eq!(Format::from_extension("jpg"), None);
        assert_eq!(Format::from_name("ps"), None);
        for f in Format::ALL {
            assert_eq!(Format::from_name(&f.to_string()), Some(f));
            assert_eq!(Format::from_extension(f.name()), Some(f));
        }
    }
}
