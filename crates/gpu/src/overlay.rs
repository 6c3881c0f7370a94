//! The debug pictures a method can draw instead of plain coverage.

/// A debug picture a method draws instead of plain coverage. With an overlay on, the
/// target's rgb holds the complete picture to show (premultiplied, over black) and its
/// alpha still holds coverage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Overlay {
    /// Pixels where the two nearest curves' distances tie (the purple regions of
    /// kocsis1david's font-demo).
    EqualDistance,
    /// Cell borders, each cell tinted by how many curves it lists.
    CellGrid,
    /// Pixels near each curve tinted by its 3-bit sign class for the ray through them.
    CurveClasses,
    /// Curves evaluated per pixel, on a colour scale.
    CostHeatMap,
    /// Triangles as wireframe, by kind.
    TriangleWireframe,
    /// Where curves were subdivided.
    SubdivisionPoints,
    /// A distance field's channels as colour.
    FieldChannels,
    /// Which of a multi-channel field's channels the median picks.
    MedianChannel,
}

impl Overlay {
    pub const ALL: [Overlay; 8] = [
        Overlay::EqualDistance,
        Overlay::CellGrid,
        Overlay::CurveClasses,
        Overlay::CostHeatMap,
        Overlay::TriangleWireframe,
        Overlay::SubdivisionPoints,
        Overlay::FieldChannels,
        Overlay::MedianChannel,
    ];

    /// The overlay called `name` (see [`Overlay::name`]); None for `none` and any name
    /// that is no overlay's.
    pub fn named(name: &str) -> Option<Overlay> {
        Overlay::ALL.into_iter().find(|o| o.name() == name)
    }

    /// The value `--param overlay=` takes.
    pub fn name(self) -> &'static str {
        match self {
            Overlay::EqualDistance => "purple",
            Overlay::CellGrid => "cells",
            Overlay::CurveClasses => "classes",
            Overlay::CostHeatMap => "cost",
            Overlay::TriangleWireframe => "wireframe",
            Overlay::SubdivisionPoints => "points",
            Overlay::FieldChannels => "channels",
            Overlay::MedianChannel => "median",
        }
    }
}
