//! The registry's table: every parameter declared once.
//!
//! Tree-level entries read
//! `id: Type = default; [min, max, step] "unit", "Group", "Label", Stage, "description";`
//! (`Stage`: the first pipeline stage the parameter affects, and the stage struct that holds
//! it: `SkeletonParams`, `MeshParams`, `FoliageParams`, `LeafParams` or `ViewerParams`),
//! per-level entries (Weber & Penn's
//! `n*`, one value per level 0..3)
//! `id: Type = [d0, d1, d2, d3]; [min, max, step] "unit", "Label", "description", trunk: bool;`.
//! The macro is `define_params!` (`params/macros.rs`).

use super::enums::{
    BarkType, CrownShape, CrownVolumeKind, Fruit, GrowthMode, LeafLod, LeafMargin, LeafOutline, LeafPhenology,
    LeafPrimaries, LeafVenation, TwigDetail,
};
use super::macros::define_params;
use super::{ParamSpec, ParamValue, Stage, GROUPS};

define_params! {
    tree {
        seed: u32 = 1; [0, 4_294_967_295u32, 1] "", "Tree", "Seed", Skeleton,
            "Random seed: the same parameters and seed always give the same tree.";
        levels: u32 = 3; [1, 4, 1] "", "Tree", "Levels", Skeleton,
            "Number of stem levels including the trunk (3 = trunk + two branch levels).";
        age: f32 = 40.0; [1.0, 300.0, 0.1] "years", "Tree", "Age", Skeleton,
            "The tree's age: below its Mature Age a younger tree, its growth replayed (each stem born the year after its parent reached it, growing along a Chapman-Richards curve); at or past it the mature tree.";
        maturity: f32 = 40.0; [1.0, 300.0, 1.0] "years", "Tree", "Mature Age", Skeleton,
            "The age at which the tree has the form its other parameters describe; each preset's Age starts here.";
        ring_width: f32 = 3.0; [0.0, 20.0, 0.1] "mm/year", "Life", "Ring Width", Skeleton,
            "Past the Mature Age, the trunk's base radius grows this much a year, and every stem thickens by the pipe model: its new wood in proportion to the shoot tips it carries.";
        shed_light: f32 = 0.25; [0.0, 1.0, 0.01] "", "Life", "Shedding Light", Skeleton,
            "Past the Mature Age, a branch whose shoots see less sky than this (0 to 1, the crown's light field) dies and drops, leaving a stub the trunk overgrows into a scar (0: none shed).";
        shed_years: f32 = 15.0; [1.0, 100.0, 1.0] "years", "Life", "Shedding Delay", Skeleton,
            "Years a branch in half the Shedding Light lives on past the Mature Age: one seeing sky s lives Delay s / (Light - s) years, so the darkest drop first and those near the threshold decades later.";
        droop: f32 = 4.0; [0.0, 30.0, 0.5] "°/decade", "Life", "Droop", Skeleton,
            "Past the Mature Age, a typical main branch sinks this much per decade under its growing load (long, slender ones more), its outer part turning up again toward the light.";
        scale: f32 = 13.0; [0.1, 100.0, 0.1] "m", "Tree", "Scale", Skeleton,
            "Overall size of the tree: trunk length = Scale x Trunk Length.";
        scale_v: f32 = 3.0; [0.0, 50.0, 0.1] "m", "Tree", "Scale Variation", Skeleton,
            "Random variation added to Scale (uniform in +/- this value).";
        scale0: f32 = 1.0; [0.1, 5.0, 0.01] "", "Trunk", "Trunk Radius Scale", Skeleton,
            "Extra scale of the trunk radius (Weber & Penn 0Scale).";
        scale0_v: f32 = 0.0; [0.0, 2.0, 0.01] "", "Trunk", "Trunk Radius Scale Variation", Skeleton,
            "Random variation of Trunk Radius Scale (uniform in +/- this value).";
        base_splits: u32 = 0; [0, 8, 1] "", "Trunk", "Base Splits", Skeleton,
            "Number of extra trunks the trunk splits into at its first joint (0BaseSplits).";
        ratio: f32 = 0.015; [0.001, 0.2, 0.001] "", "Tree", "Radius Ratio", Skeleton,
            "Trunk base radius as a fraction of the trunk length.";
        ratio_power: f32 = 1.2; [0.0, 5.0, 0.05] "", "Tree", "Ratio Power", Skeleton,
            "How fast child radii shrink with their length relative to the parent (r_child = r_parent (L/L_parent)^power).";
        attraction_up: f32 = 0.5; [-10.0, 10.0, 0.05] "", "Tree", "Attraction Up", Skeleton,
            "Bends branches of level 2 and deeper toward the sky (positive) or the ground (negative: weeping).";
        shape: CrownShape = CrownShape::Cylindrical; [0, 8, 1] "", "Crown", "Crown Shape", Skeleton,
            "Envelope that sets level-1 branch length by height on the trunk (Weber & Penn ShapeRatio); Drawn follows the crown outline drawn by hand (Cylindrical until one is drawn).";
        base_size: f32 = 0.4; [0.0, 1.0, 0.01] "", "Crown", "Base Size", Skeleton,
            "Fraction of the trunk, from the ground, that carries no branches; the crown starts above it.";
        angle_spread: f32 = 0.0; [-45.0, 45.0, 0.5] "°", "Crown", "Angle Spread", Skeleton,
            "Height-based down-angle offset: positive points top branches upward and base branches outward.";
        show_preview: bool = false; [0, 1, 1] "", "Crown", "Show Preview", Viewer,
            "Viewer only: draw the crown envelope (maximum branch reach at each height) as a wireframe.";
        prune_ratio: f32 = 0.0; [0.0, 1.0, 0.01] "", "Crown", "Prune Ratio", Skeleton,
            "How strongly branches are shortened to fit the pruning envelope (0 = off, 1 = fully).";
        prune_width: f32 = 0.5; [0.01, 5.0, 0.01] "", "Crown", "Prune Width", Skeleton,
            "Width of the pruning envelope as a fraction of the tree scale.";
        prune_width_peak: f32 = 0.5; [0.0, 1.0, 0.01] "", "Crown", "Prune Width Peak", Skeleton,
            "Where the pruning envelope is widest, as a fraction of the crown from its base.";
        prune_power_low: f32 = 0.5; [0.0, 10.0, 0.01] "", "Crown", "Prune Power Low", Skeleton,
            "Curvature of the pruning envelope below its widest point.";
        prune_power_high: f32 = 0.5; [0.0, 10.0, 0.01] "", "Crown", "Prune Power High", Skeleton,
            "Curvature of the pruning envelope above its widest point.";
        flare: f32 = 0.6; [0.0, 5.0, 0.05] "", "Trunk", "Flare", Skeleton,
            "Widening of the trunk toward the ground over its lowest eighth.";
        lobes: u32 = 5; [0, 20, 1] "", "Trunk", "Lobes", Mesh,
            "Number of lobes (flutes) around the trunk cross-section; 0 = round.";
        lobe_depth: f32 = 0.07; [0.0, 1.0, 0.01] "", "Trunk", "Lobe Depth", Mesh,
            "Depth of the trunk lobes as a fraction of the radius.";
        weld: bool = true; [0, 1, 1] "", "Trunk", "Welded Forks", Mesh,
            "Weld levels 1 and 2 and split clones into their parent's surface with a smooth collar (one closed surface); off = every branch is a separate closed tube.";
        weld_collar: f32 = 1.0; [0.0, 3.0, 0.05] "", "Trunk", "Branch Collar", Mesh,
            "Size of the welded branch collar, in branch radii: how much wider than the branch its footprint on the parent is and how far out the collar blends into it.";
        guide_xy: f32 = 0.0; [0.0, 5.0, 0.01] "m", "Trunk", "Guide Limit", Skeleton,
            "Complex trunk: random sideways offset of each trunk point (the guide curve), within this limit (0 = off).";
        refine_curves: u32 = 0; [0, 12, 1] "", "Trunk", "Refinement Curves", Mesh,
            "Complex trunk: number of shape-refinement curves around the trunk; their circles merge into a fluted, buttressed outline (0 = off).";
        refine_offset: f32 = 1.0; [0.0, 2.0, 0.01] "", "Trunk", "Refinement Offset", Mesh,
            "Complex trunk: distance of the refinement curves from the trunk axis, as a fraction of the trunk radius (1 = on its surface).";
        refine_radius: f32 = 0.333; [0.05, 1.0, 0.01] "", "Trunk", "Refinement Radius", Mesh,
            "Complex trunk: radius of the refinement circles as a fraction of the trunk radius (default one third).";
        refine_variation: f32 = 0.3; [0.0, 1.0, 0.01] "", "Trunk", "Refinement Variation", Mesh,
            "Complex trunk: random variation of each refinement circle's offset and radius along the height.";
        base_ripple: f32 = 0.0; [0.0, 0.5, 0.01] "", "Trunk", "Base Ripple", Mesh,
            "Ripple of the trunk base, R(u) = R0 (1 + a sin 7u), fading out over the flare zone (0 = off).";
        root_count: u32 = 0; [0, 16, 1] "", "Trunk", "Roots", Skeleton,
            "Number of surface roots spreading from the trunk base (0 = none).";
        root_length: f32 = 0.15; [0.01, 1.0, 0.01] "", "Trunk", "Root Length", Skeleton,
            "Length of the surface roots as a fraction of the trunk length.";
        root_radius: f32 = 0.35; [0.05, 1.0, 0.01] "", "Trunk", "Root Radius", Skeleton,
            "Thickness of the roots where they leave the trunk, as a fraction of the trunk radius.";
        root_spread: f32 = 0.4; [0.0, 1.0, 0.01] "", "Trunk", "Root Spread", Skeleton,
            "Random variation of the roots' directions and lengths (0 = evenly spaced, equal).";
        root_depth: f32 = 0.6; [0.0, 3.0, 0.05] "", "Trunk", "Root Depth", Skeleton,
            "How far the roots dive below the ground toward their tips, in root radii (0 = along the surface).";
        hole_count: u32 = 0; [0, 16, 1] "", "Trunk", "Holes", Mesh,
            "Number of tree holes cut into the trunk (and level-1 stems at least Hole Min Radius thick), at concave spots of the bark, below big branch junctions and between root starts (0 = none). Fewer are cut where there is no room, or when a hole would pass the vertex budget.";
        hole_size: f32 = 0.35; [0.05, 1.0, 0.01] "", "Trunk", "Hole Size", Mesh,
            "Half-width of a hole's opening as a fraction of the local stem radius (holes are 1.5 times taller than wide).";
        hole_depth: f32 = 0.5; [0.05, 0.9, 0.01] "", "Trunk", "Hole Depth", Mesh,
            "Depth of the cavity behind a hole, as a fraction of the local stem radius.";
        hole_min_radius: f32 = 0.1; [0.0, 5.0, 0.01] "m", "Trunk", "Hole Min Radius", Mesh,
            "Holes are cut only where the stem's local radius is at least this.";
        hole_seed: u32 = 0; [0, 4_294_967_295u32, 1] "", "Trunk", "Hole Seed", Mesh,
            "Random seed of the hole placement: picks other candidate spots without changing the tree.";
        bark_type: BarkType = BarkType::Furrowed; [0, 3, 1] "", "Trunk", "Bark Type", Mesh,
            "Bark pattern: Furrowed ridges (oak), Plated with dark cracks (pine, fir), Smooth-banded pale skin with lenticels (birch, aspen) or Fibrous criss-cross strips (willow, cypress); its size follows each stem's girth and thin stems turn smooth young bark.";
        twig_detail: TwigDetail = TwigDetail::Four; [0, 3, 1] "", "Quality", "Twig Detail", Mesh,
            "Bezier twigs (the thinnest stems): step along the control circle, 1 = four times the sides a tube of that radius gets, 4 = the same, 8 = half.";
        growth_mode: GrowthMode = GrowthMode::Parametric; [0, 1, 1] "", "Growth", "Growth Mode", Skeleton,
            "Parametric draws the tree with Weber & Penn's rules; Space Colonization grows it toward markers in a crown volume.";
        growth_age: f32 = 1.0; [0.0, 1.0, 0.01] "", "Growth", "Age", Skeleton,
            "Space colonization: show the tree as it was after this fraction of its growth iterations.";
        markers: u32 = 2_000; [10, 50_000, 10] "", "Growth", "Markers", Skeleton,
            "Space colonization: number of attraction points (markers) sampled in the crown volume.";
        extra_markers: u32 = 0; [0, 20_000, 10] "", "Growth", "Extra Markers", Skeleton,
            "Space colonization: markers added per 1,000 iterations while growing (bushier interiors).";
        influence_radius: f32 = 3.0; [0.05, 50.0, 0.05] "m", "Growth", "Influence Radius", Skeleton,
            "Space colonization: a marker attracts the closest growing node within this distance.";
        kill_distance: f32 = 0.6; [0.01, 20.0, 0.01] "m", "Growth", "Kill Distance", Skeleton,
            "Space colonization: a marker is removed when a node comes this close.";
        internode: f32 = 0.3; [0.02, 5.0, 0.01] "m", "Growth", "Internode", Skeleton,
            "Space colonization: length of one growth step.";
        iterations: u32 = 400; [1, 5_000, 1] "", "Growth", "Iterations", Skeleton,
            "Space colonization: iteration cap (growth also stops when no marker is left or nothing grows).";
        tropism: f32 = 0.1; [-1.0, 1.0, 0.01] "", "Growth", "Tropism", Skeleton,
            "Space colonization: pull of every growth step toward the sky (positive) or the ground (negative).";
        growth_jitter: f32 = 0.1; [0.0, 1.0, 0.01] "", "Growth", "Jitter", Skeleton,
            "Space colonization: random deviation of growth directions.";
        apical_control: f32 = 0.3; [0.0, 1.0, 0.01] "", "Growth", "Apical Control", Skeleton,
            "Space colonization: chance that a node which already has a shoot does not sprout again (fewer side branches).";
        start_points: u32 = 1; [1, 20, 1] "", "Growth", "Start Points", Skeleton,
            "Space colonization: number of trunks, in a row along x (more than one makes a hedgerow).";
        start_spacing: f32 = 2.0; [0.1, 20.0, 0.1] "m", "Growth", "Start Spacing", Skeleton,
            "Space colonization: distance between neighbouring start points.";
        tip_radius: f32 = 0.008; [0.001, 0.1, 0.001] "m", "Growth", "Tip Radius", Skeleton,
            "Space colonization: radius of the branch tips; thicker stems follow the pipe model.";
        pipe_power: f32 = 2.0; [1.0, 4.0, 0.05] "", "Growth", "Pipe Power", Skeleton,
            "Space colonization: pipe model exponent D in r_parent^D = sum of r_child^D (2 = da Vinci's rule).";
        crown_volume: CrownVolumeKind = CrownVolumeKind::Ellipsoid; [0, 2, 1] "", "Growth Volume", "Crown Volume", Skeleton,
            "Space colonization: markers fill an ellipsoid, the Crown Shape envelope as a solid of revolution, or the union of your crown primitives.";
        crown_base: f32 = 2.5; [0.0, 50.0, 0.1] "m", "Growth Volume", "Crown Bottom", Skeleton,
            "Space colonization: height of the bottom of the crown volume above the ground.";
        crown_height: f32 = 6.0; [0.2, 100.0, 0.1] "m", "Growth Volume", "Crown Height", Skeleton,
            "Space colonization: height of the crown volume.";
        crown_radius: f32 = 3.5; [0.1, 50.0, 0.1] "m", "Growth Volume", "Crown Radius", Skeleton,
            "Space colonization: largest horizontal radius of the crown volume.";
        marker_surface_bias: f32 = 0.0; [-1.0, 1.0, 0.05] "", "Growth Volume", "Surface Bias", Skeleton,
            "Space colonization: crowd markers toward the crown's surface (positive) or its axis (negative).";
        marker_top_bias: f32 = 0.0; [-1.0, 1.0, 0.05] "", "Growth Volume", "Top Bias", Skeleton,
            "Space colonization: crowd markers toward the top (positive) or the bottom (negative) of the crown.";
        show_markers: bool = false; [0, 1, 1] "", "Growth Volume", "Show Markers", Viewer,
            "Viewer only: draw the growth markers (attraction points) as dots.";
        show_volumes: bool = false; [0, 1, 1] "", "Growth Volume", "Show Volumes", Viewer,
            "Viewer only: draw the crown volume, the wall and your primitives as wireframes, with drag handles.";
        light_competition: bool = false; [0, 1, 1] "", "Environment", "Light Competition", Skeleton,
            "Space colonization: reject new shoots that would grow in the shade of the canopy above them.";
        shade_depth: f32 = 4.0; [0.5, 50.0, 0.5] "", "Environment", "Shade Depth", Skeleton,
            "Space colonization: how many internodes of canopy above a shoot put it in the shade.";
        wall: bool = false; [0, 1, 1] "", "Environment", "Wall", Skeleton,
            "Space colonization: a wall beside the tree: branches stop at it and it shades the markers near it.";
        wall_distance: f32 = 1.5; [0.2, 50.0, 0.1] "m", "Environment", "Wall Distance", Skeleton,
            "Space colonization: distance from the trunk to the wall.";
        wall_height: f32 = 8.0; [0.5, 100.0, 0.1] "m", "Environment", "Wall Height", Skeleton,
            "Space colonization: height of the wall.";
        wall_width: f32 = 12.0; [0.5, 200.0, 0.1] "m", "Environment", "Wall Width", Skeleton,
            "Space colonization: length of the wall.";
        leaves: u32 = 25; [0, 1_000, 1] "", "Foliage", "Leaves", Foliage,
            "Leaves per stem of the last branch level (Weber & Penn Leaves; grown trees: per outermost shoot); 0 = bare.";
        foliage_scale: f32 = 0.17; [0.01, 5.0, 0.01] "m", "Foliage", "Leaf Scale", Foliage,
            "Leaf length, base to tip (Weber & Penn LeafScale).";
        foliage_scale_x: f32 = 1.0; [0.05, 5.0, 0.01] "", "Foliage", "Leaf Scale X", Foliage,
            "Extra scale of the leaf width (Weber & Penn LeafScaleX).";
        foliage_start: f32 = 0.0; [0.0, 0.95, 0.01] "", "Foliage", "Leaf Start", Foliage,
            "Fraction of each stem, from its base, that carries no leaves.";
        foliage_distribution: f32 = 0.0; [-1.0, 1.0, 0.05] "", "Foliage", "Leaf Distribution", Foliage,
            "Where leaves crowd along a stem: positive toward the tip, negative toward the base, 0 = even.";
        foliage_angle: f32 = 45.0; [0.0, 90.0, 1.0] "°", "Foliage", "Leaf Angle", Foliage,
            "Angle between a leaf and its stem before it turns toward the light.";
        foliage_size_v: f32 = 0.2; [0.0, 0.9, 0.01] "", "Foliage", "Size Variation", Foliage,
            "Random variation of the leaf size (uniform in +/- this fraction).";
        foliage_clumping: f32 = 0.0; [0.0, 1.0, 0.01] "", "Foliage", "Clumping", Foliage,
            "Pulls leaves together into clumps of about five along the stem (0 = evenly spread).";
        foliage_twigs3: bool = false; [0, 1, 1] "", "Foliage", "Three-Leaf Twigs", Foliage,
            "Each leaf position carries a small twig of three leaves (a centre leaf and two side leaves).";
        foliage_color_v: f32 = 0.15; [0.0, 1.0, 0.01] "", "Foliage", "Colour Variation", Foliage,
            "Random per-leaf tint: brightness and a shift toward yellow.";
        season: f32 = 7.0; [1.0, 12.99, 0.05] "month", "Foliage", "Season", Foliage,
            "Month of the year (northern temperate; 1 = 1 January, 7.5 = mid-July): spring leaves flush small and pale, autumn leaves turn by species and light (sun leaves first) and fall, deciduous trees are bare in winter and conifers bronze slightly. July (the default) is the summer tree.";
        organs: bool = true; [0, 1, 1] "", "Flowers & Fruit", "Flowers & Fruit", Foliage,
            "Through the Season: blossom (cherry, apple) and catkins (birch, aspen, willow) in spring, the Fruit in its months, buds at the shoot tips of bare deciduous trees in winter.";
        fruit: Fruit = Fruit::None; [0, 6, 1] "", "Flowers & Fruit", "Fruit", Foliage,
            "The fruit the tree bears in its months: acorns (August to November), samaras (August to November), hanging or upright cones (from August), cherries (May to June), apples (June to October).";
        fruit_load: f32 = 0.3; [0.0, 1.0, 0.01] "", "Flowers & Fruit", "Fruit Load", Foliage,
            "Fraction of the leafy shoots that carry flowers and fruit (each shoot one cluster near its tip).";
        fallen_leaves: bool = true; [0, 1, 1] "", "Flowers & Fruit", "Fallen Leaves", Foliage,
            "Leaves that fell lie on the ground under the crown, from their fall until the next spring.";
        leaf_years: f32 = 0.0; [0.0, 100.0, 1.0] "years", "Life", "Leafy Years", Foliage,
            "Leaves only on wood grown in the last this many years (the youngest shoots): older, inner wood goes bare (0: leaves on all wood).";
        foliage_lod: LeafLod = LeafLod::Auto; [0, 3, 1] "", "Foliage", "Leaf Mesh", Leaf,
            "Geometry drawn for every leaf: Auto (the full blade while the foliage stays under 200,000 triangles, else billboards, else cards), Blade, Billboards or Card.";
        mesh_quality: f32 = 1.0; [0.25, 4.0, 0.05] "", "Quality", "Mesh Quality", Mesh,
            "Multiplies the number of sides around each stem and rings along bends.";
        max_vertices: u32 = 2_000_000; [1_000, 20_000_000, 1_000] "", "Budget", "Max Vertices", Skeleton,
            "Vertex budget: a tree that would need more stops with an error instead of freezing.";
        max_leaves: u32 = 500_000; [0, 5_000_000, 1_000] "", "Budget", "Max Leaves", Foliage,
            "Leaf budget: a tree that would need more leaves stops with an error instead of freezing.";
        leaf_outline: LeafOutline = LeafOutline::Pinnate; [0, 3, 1] "", "Leaf", "Leaf Outline", Leaf,
            "How the blade outline is drawn: Gielis' superformula, a mirrored cubic spline (Spline Angle 1, L1, Angle 2, L2), a Pinnate blade (profile along the midrib, lobes along it) or a Palmate one (lobes from the petiole).";
        leaf_base_shape: f32 = 0.7; [0.15, 3.0, 0.05] "", "Leaf", "Base Shape", Leaf,
            "Pinnate outline: exponent of the blade profile at the base; below 1 rounded or truncate, 1 wedge-shaped, above 1 tapering.";
        leaf_tip_shape: f32 = 0.95; [0.15, 3.0, 0.05] "", "Leaf", "Tip Shape", Leaf,
            "Pinnate outline: exponent of the blade profile at the tip; below 1 rounded, 1 acute, above 1 drawn out (acuminate). With Base Shape it puts the widest point at base / (base + tip).";
        leaf_lobes: u32 = 0; [0, 15, 1] "", "Leaf", "Lobes", Leaf,
            "Pinnate outline: lobes on each side along the midrib (the tip is a terminal lobe); Palmate outline: lobes in all, radiating from the petiole (an odd count has one at the tip). 0 = none.";
        leaf_lobe_depth: f32 = 0.5; [0.0, 0.95, 0.01] "", "Leaf", "Sinus Depth", Leaf,
            "How far the sinuses between lobes cut in: a fraction of the half-width (Pinnate) or of the lobe's length (Palmate).";
        leaf_lobe_point: f32 = 0.0; [0.0, 1.0, 0.01] "", "Leaf", "Lobe Point", Leaf,
            "Lobe shape: 0 = rounded lobes (oak, ginkgo), 1 = pointed lobes leaning toward the tip (maple, birch's large teeth).";
        leaf_lobe_spread: f32 = 120.0; [10.0, 175.0, 1.0] "°", "Leaf", "Lobe Spread", Leaf,
            "Palmate outline: angle between the tip's direction and the lowest lobe, seen from the petiole.";
        leaf_lobe_teeth: u32 = 0; [0, 6, 1] "", "Leaf", "Lobe Teeth", Leaf,
            "Palmate outline: large pointed teeth on each flank of every lobe (a Norway maple has two or three).";
        leaf_petiole: f32 = 0.6; [0.0, 2.0, 0.01] "", "Leaf", "Petiole Length", Foliage,
            "Leaf stalk between the twig and the blade (leaf lengths); the tree hangs the blade this far from its stem.";
        leaf_petiole_flat: bool = true; [0, 1, 1] "", "Leaf", "Flat Petiole", Leaf,
            "The petiole is flattened sideways, across the blade's plane, so the leaf flutters in the lightest wind (aspens, poplars).";
        leaf_phenology: LeafPhenology = LeafPhenology::Aspen; [0, 9, 1] "", "Leaf", "Phenology", Foliage,
            "Whose calendar and autumn colours the leaves follow through the Season: when they leaf out, turn and fall, and their autumn palette (aspen, birch, ginkgo and willow yellow, maple scarlet to orange, oak russet and brown, tupelo crimson); an Evergreen Conifer keeps its needles.";
        leaf_fascicle: u32 = 1; [1, 5, 1] "", "Leaf", "Needles per Fascicle", Leaf,
            "1 = one leaf; 2 to 5 = a pine fascicle: that many round needles (the outline's length and width) from one sheath.";
        leaf_shoot: u32 = 0; [0, 120, 1] "", "Leaf", "Needles per Shoot", Leaf,
            "0 = the leaf is one blade (or one fascicle). 1 to 120: the leaf is a conifer shoot, a twig one leaf long carrying that many needles (or fascicles), drawn as geometry and baked into one texture, so a crown of shoots has a real conifer's needle mass.";
        leaf_shoot_flat: bool = false; [0, 1, 1] "", "Leaf", "Flat Shoot", Leaf,
            "Shoots: the needles twist into two flat ranks, left and right of the twig (firs, yews); off, they stand all around it (spruces, pines, cypresses).";
        leaf_shoot_angle: f32 = 55.0; [5.0, 90.0, 1.0] "°", "Leaf", "Needle Angle", Leaf,
            "Shoots: angle between a needle and its twig (the youngest, at the tip, point further forward).";
        leaf_shoot_needle: f32 = 0.3; [0.05, 1.0, 0.01] "", "Leaf", "Needle Length", Leaf,
            "Shoots: a needle's length as a fraction of the shoot's; its width is the outline's Aspect Ratio of that.";
        leaf_m: f32 = 2.0; [0.0, 20.0, 0.5] "", "Leaf", "Symmetry (m)", Leaf,
            "Superformula m: number of symmetry axes; odd values put a lobe at the tip and a sinus at the base.";
        leaf_a: f32 = 1.0; [0.05, 4.0, 0.01] "", "Leaf", "Superformula a", Leaf,
            "Superformula a: divides the cosine term; with b it sets how the blade narrows toward the tip.";
        leaf_b: f32 = 0.6; [0.01, 4.0, 0.01] "", "Leaf", "Superformula b", Leaf,
            "Superformula b: divides the sine term; below a the blade narrows toward the tip.";
        leaf_n1: f32 = 2.5; [0.2, 40.0, 0.1] "", "Leaf", "Superformula n1", Leaf,
            "Superformula n1: overall exponent; small values pinch the outline, large values round it.";
        leaf_n2: f32 = 8.0; [0.2, 40.0, 0.1] "", "Leaf", "Superformula n2", Leaf,
            "Superformula n2: exponent of the cosine term.";
        leaf_n3: f32 = 8.0; [0.2, 40.0, 0.1] "", "Leaf", "Superformula n3", Leaf,
            "Superformula n3: exponent of the sine term.";
        leaf_aspect: f32 = 1.0; [0.02, 2.0, 0.01] "", "Leaf", "Aspect Ratio", Leaf,
            "Blade width as a fraction of its length (superformula outline).";
        leaf_angle1: f32 = 70.0; [5.0, 90.0, 1.0] "°", "Leaf", "Spline Angle 1", Leaf,
            "Spline outline: angle between the midrib and the edge where it leaves the base.";
        leaf_l1: f32 = 1.0; [0.05, 1.0, 0.01] "", "Leaf", "Spline L1", Leaf,
            "Spline outline: length of the base handle (leaf lengths).";
        leaf_angle2: f32 = 70.0; [5.0, 90.0, 1.0] "°", "Leaf", "Spline Angle 2", Leaf,
            "Spline outline: angle between the midrib and the edge where it arrives at the tip.";
        leaf_l2: f32 = 1.0; [0.05, 1.0, 0.01] "", "Leaf", "Spline L2", Leaf,
            "Spline outline: length of the tip handle (leaf lengths).";
        leaf_margin: LeafMargin = LeafMargin::Crenate; [0, 4, 1] "", "Leaf", "Margin", Leaf,
            "Edge detail: Entire, Serrate (teeth lean toward the tip), Dentate, Crenate or Lobed.";
        leaf_teeth: u32 = 44; [0, 200, 1] "", "Leaf", "Tooth Count", Leaf,
            "Teeth (or lobes) around the whole margin; the tip is always a tooth.";
        leaf_tooth_depth: f32 = 0.035; [0.0, 1.0, 0.01] "", "Leaf", "Tooth Depth", Leaf,
            "How far teeth stand out: the edge radius is multiplied by 1 + depth x wave.";
        leaf_tooth_sharpness: f32 = 0.5; [0.0, 1.0, 0.01] "", "Leaf", "Tooth Sharpness", Leaf,
            "Serrate only: how far each tooth leans toward the tip (0 = upright, 1 = hooked).";
        leaf_asymmetry_seed: u32 = 0; [0, 4_294_967_295u32, 1] "", "Leaf", "Asymmetry Seed", Leaf,
            "Seed of small per-tooth and per-side differences between the halves, and of irregular pinnate lobes (uneven spacing, sinus depth and reach); 0 = exactly mirror-symmetric, regular lobes.";
        leaf_detail: f32 = 1.0; [0.25, 4.0, 0.05] "", "Leaf", "Outline Detail", Leaf,
            "Multiplies the density of the curvature-adaptive outline sampling.";
        leaf_rings: u32 = 5; [1, 16, 1] "", "Leaf", "Rings", Leaf,
            "Concentric rings of the blade triangulation (interior detail).";
        leaf_venation: LeafVenation = LeafVenation::Open; [0, 3, 1] "", "Leaf Veins", "Venation", Leaf,
            "Vein network: None, Open or Closed space colonization (Runions 2005), or Spline veins.";
        leaf_vein_seed: u32 = 1; [0, 4_294_967_295u32, 1] "", "Leaf Veins", "Vein Seed", Leaf,
            "Seed of the auxin sources and of the spline veins' variation.";
        leaf_vein_density: f32 = 800.0; [0.0, 20_000.0, 10.0] "", "Leaf Veins", "Vein Density", Leaf,
            "Auxin sources per unit area (leaf length 1); at most 5,000 sources.";
        leaf_attraction: f32 = 0.08; [0.005, 0.5, 0.005] "", "Leaf Veins", "Attraction Distance", Leaf,
            "A source pulls vein nodes within this distance (leaf lengths); must exceed Kill Distance.";
        leaf_kill: f32 = 0.02; [0.002, 0.05, 0.001] "", "Leaf Veins", "Kill Distance", Leaf,
            "A source dies when a vein comes this close (leaf lengths).";
        leaf_growth_step: f32 = 0.01; [0.002, 0.05, 0.001] "", "Leaf Veins", "Growth Step", Leaf,
            "Length a vein grows per iteration (leaf lengths).";
        leaf_vein_width: f32 = 0.02; [0.001, 0.1, 0.001] "", "Leaf Veins", "Vein Width", Leaf,
            "Midrib width at the base (leaf lengths); every vein is this x sqrt(tips downstream / all tips) (pipe model).";
        leaf_vein_count: u32 = 7; [1, 40, 1] "", "Leaf Veins", "Spline Veins", Leaf,
            "Spline venation: lateral veins per side.";
        leaf_vein_var: f32 = 0.0; [0.0, 1.0, 0.01] "", "Leaf Veins", "Spline Variation", Leaf,
            "Spline venation: random shift of where the veins leave the midrib.";
        leaf_vein_squish: f32 = 0.5; [0.05, 1.0, 0.01] "", "Leaf Veins", "Spline Squish", Leaf,
            "Spline venation: how far the veins bunch toward the tip (1 = spread over the whole midrib).";
        leaf_vein_up: f32 = 0.5; [0.0, 1.0, 0.01] "", "Leaf Veins", "Spline Up", Leaf,
            "Spline venation: control points lie on the edge scaled toward the midrib by this (low = pinnate, high = arcuate).";
        leaf_primary_veins: LeafPrimaries = LeafPrimaries::Pinnate; [0, 3, 1] "", "Leaf Veins", "Primary Veins", Leaf,
            "Veins laid down before space colonization fills the rest: None, Pinnate (midrib and secondaries, one per lobe), Palmate (one per lobe from the petiole junction) or Dichotomous (forking in two, ginkgo).";
        leaf_secondaries: u32 = 6; [0, 30, 1] "", "Leaf Veins", "Secondary Veins", Leaf,
            "Pinnate primaries on an unlobed blade: secondary veins per side, each ending in the nearest tooth.";
        leaf_secondary_angle: f32 = 45.0; [10.0, 85.0, 1.0] "°", "Leaf Veins", "Secondary Angle", Leaf,
            "Angle between a secondary vein and the midrib where it leaves it.";
        leaf_midrib_curvature: f32 = 0.1; [-1.0, 1.0, 0.01] "", "Leaf Surface", "Midrib Curvature", Leaf,
            "Bends the leaf along its length (positive lifts the tip toward the front, +Z).";
        leaf_cross_curvature: f32 = 0.1; [-1.0, 1.0, 0.01] "", "Leaf Surface", "Cross Curvature", Leaf,
            "Cups the blade across its width (positive lifts both edges toward the front).";
        leaf_edge_curl: f32 = 0.0; [-1.0, 1.0, 0.01] "", "Leaf Surface", "Edge Curl", Leaf,
            "Curls the margin toward the front (positive) or back: most at the edge, none at the centre.";
        leaf_vein_displacement: f32 = 0.004; [0.0, 0.05, 0.001] "", "Leaf Surface", "Vein Displacement", Leaf,
            "Height of the vein ridges (leaf lengths); thicker veins raise higher and wider ridges.";
        leaf_texture_level: u32 = 8; [4, 11, 1] "", "Leaf Surface", "Texture Size (log2)", Leaf,
            "The baked vein texture is 2^value texels high; its width is the power of two nearest the blade's aspect.";
        leaf_impostor_grid: u32 = 8; [2, 16, 1] "", "Leaf Surface", "Impostor Grid", Leaf,
            "Impostor view directions: an N x N hemi-octahedral grid over the leaf's front hemisphere.";
    }
    level {
        length: f32 = [1.0, 0.3, 0.6, 0.4]; [0.0, 2.0, 0.01] "", "Length",
            "Stem length: trunk as a fraction of Scale; level 1 relative to the parent (times the crown shape); deeper levels relative to the parent's remaining length.", trunk: true;
        length_v: f32 = [0.0, 0.0, 0.0, 0.0]; [0.0, 1.0, 0.01] "", "Length Variation",
            "Random variation added to Length (uniform in +/- this value).", trunk: true;
        taper: f32 = [1.0, 1.0, 1.0, 1.0]; [0.0, 3.0, 0.01] "", "Taper",
            "Radius taper: 0 = cylinder, 1 = cone to a point, 1-2 = rounded tip, 2-3 = periodic bulges.", trunk: true;
        curve_res: u32 = [3, 5, 3, 1]; [1, 50, 1] "", "Curve Resolution",
            "Number of segments the stem is built from; each can bend.", trunk: true;
        curve: f32 = [0.0, -40.0, -40.0, 0.0]; [-360.0, 360.0, 1.0] "°", "Curve",
            "Total bend of the stem from base to tip (negative bends downward).", trunk: true;
        curve_back: f32 = [0.0, 0.0, 0.0, 0.0]; [-360.0, 360.0, 1.0] "°", "Curve Back",
            "Bend of the second half of the stem, for S-shaped stems (0 = one even bend).", trunk: true;
        curve_v: f32 = [20.0, 50.0, 75.0, 0.0]; [-360.0, 360.0, 1.0] "°", "Curve Variation",
            "Random bend per stem (uniform in +/- this value over its segments); negative winds the stem into a helix of that angle.", trunk: true;
        seg_splits: f32 = [0.0, 0.0, 0.0, 0.0]; [0.0, 2.0, 0.01] "", "Segment Splits",
            "Clones made at each joint of the stem (fractions accumulate: 0.25 = one split every four joints).", trunk: true;
        split_angle: f32 = [0.0, 0.0, 0.0, 0.0]; [0.0, 180.0, 1.0] "°", "Split Angle",
            "Angle between the clones of a split (less the stem's declination).", trunk: true;
        split_angle_v: f32 = [0.0, 0.0, 0.0, 0.0]; [0.0, 180.0, 1.0] "°", "Split Angle Variation",
            "Random variation of Split Angle (uniform in +/- this value).", trunk: true;
        down_angle: f32 = [0.0, 60.0, 45.0, 45.0]; [-179.0, 179.0, 1.0] "°", "Down Angle",
            "Angle between a branch and its parent stem.", trunk: false;
        down_angle_v: f32 = [0.0, -50.0, 10.0, 10.0]; [-179.0, 179.0, 1.0] "°", "Down Angle Variation",
            "Random variation of Down Angle; negative values make it depend on the position along the parent instead.", trunk: false;
        rotate: f32 = [0.0, 140.0, 140.0, 77.0]; [-360.0, 360.0, 1.0] "°", "Rotate",
            "Angle around the parent from one branch to the next (negative: alternate sides at 180 + value).", trunk: false;
        rotate_v: f32 = [0.0, 0.0, 0.0, 0.0]; [0.0, 360.0, 1.0] "°", "Rotate Variation",
            "Random variation of Rotate (uniform in +/- this value).", trunk: false;
        branches: u32 = [0, 50, 30, 10]; [0, 500, 1] "", "Branches",
            "Number of child branches (level 1: on the trunk; deeper: per parent, scaled by the parent's length).", trunk: false;
    }
}
