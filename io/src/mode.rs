//! What a run computes: the pipeline's stages from a delivery or a launch
//! (the compute module runs them, the report module lays out their columns).

/// What a run computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Delivery → launch.
    Impact,
    /// Launch → flight.
    Flight,
    /// Delivery → launch → flight.
    Shot,
}
