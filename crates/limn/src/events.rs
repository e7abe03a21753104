//! What a render tells its caller while it runs: warnings as they arise, and the stage
//! it is in (for a progress display).

/// Receives a render's warnings and stages.
pub trait Events {
    /// A warning: something the user gave that the picture does not show as given.
    fn warning(&mut self, text: &str);
    /// The render entered a stage (`ordering`, `writing`, `rendering`, …).
    fn phase(&mut self, _name: &'static str) {}
}

/// Events that go nowhere (the warnings are still in the result's statistics).
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Events for Silent {
    fn warning(&mut self, _text: &str) {}
}

/// Events collected: the warnings in order.
#[derive(Debug, Clone, Default)]
pub struct Collected {
    /// The warnings.
    pub warnings: Vec<String>,
}

impl Events for Collected {
    fn warning(&mut self, text: &str) {
        self.warnings.push(text.to_string());
    }
}
