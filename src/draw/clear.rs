//! What a label must keep clear of, indexed by cells of the panel: the
//! labels placed so far, the points (frame origins, axis tips, colour
//! probes) and the sample points of the lines drawn. A label's place is
//! then tested against what lies in the few cells around it, not against
//! every mark, so laying out n frames takes time linear in n (20,000 frames
//! in about a second) with the same choices as testing every mark.

/// The side of a cell in pixels.
const CELL: f64 = 8.0;

/// How far outside a label a point still counts as under it (pixels).
const PAD: f64 = 3.0;

/// A label's box: left, top, right, bottom in pixels.
pub(super) type Rect = (f64, f64, f64, f64);

/// One kind of thing to keep clear of, by cell: points, or boxes.
struct Cells<T> {
    /// Cell (0, 0)'s top left corner in pixels.
    x0: f64,
    y0: f64,
    cols: usize,
    rows: usize,
    cells: Vec<Vec<T>>,
}

impl<T> Cells<T> {
    /// Cells covering `area` with a margin of two cells.
    fn new(area: Rect) -> Cells<T> {
        let x0 = area.0 - 2.0 * CELL;
        let y0 = area.1 - 2.0 * CELL;
        let cols = ((area.2 - x0) / CELL).ceil() as usize + 2;
        let rows = ((area.3 - y0) / CELL).ceil() as usize + 2;
        Cells {
            x0,
            y0,
            cols,
            rows,
            cells: (0..cols * rows).map(|_| Vec::new()).collect(),
        }
    }

    /// The cell column of `x` (clamped to the index; NaN is column 0).
    fn col(&self, x: f64) -> usize {
        (((x - self.x0) / CELL).floor().max(0.0) as usize).min(self.cols - 1)
    }
    fn row(&self, y: f64) -> usize {
        (((y - self.y0) / CELL).floor().max(0.0) as usize).min(self.rows - 1)
    }

    /// Whether (x, y) lies within the cells' area.
    fn covers(&self, x: f64, y: f64) -> bool {
        x >= self.x0
            && y >= self.y0
            && x < self.x0 + self.cols as f64 * CELL
            && y < self.y0 + self.rows as f64 * CELL
    }

    /// The cells that meet the rectangle `r`: (index, whether the cell lies
    /// wholly inside `r`).
    fn meeting(&self, r: Rect) -> impl Iterator<Item = (usize, bool)> + '_ {
        let (c0, c1, r0, r1) = (self.col(r.0), self.col(r.2), self.row(r.1), self.row(r.3));
        (r0..=r1).flat_map(move |row| {
            (c0..=c1).map(move |col| {
                let (left, top) = (self.x0 + col as f64 * CELL, self.y0 + row as f64 * CELL);
                let inside = left > r.0 && left + CELL < r.2 && top > r.1 && top + CELL < r.3;
                (row * self.cols + col, inside)
            })
        })
    }
}

/// Everything placed in one panel that a label must keep clear of.
pub(super) struct Clear {
    /// Origins, axis tips and probes: a label keeps clear of them always.
    points: Cells<(f64, f64)>,
    /// Sample points of the lines drawn, every 3 pixels: kept clear of
    /// where a place allows it (the strict pass).
    lines: Cells<(f64, f64)>,
    /// The labels placed so far.
    boxes: Cells<Rect>,
}

impl Clear {
    /// An empty index for labels that lie within `area`.
    pub(super) fn new(area: Rect) -> Clear {
        Clear {
            points: Cells::new(area),
            lines: Cells::new(area),
            boxes: Cells::new(area),
        }
    }

    /// A point to keep clear of.
    pub(super) fn point(&mut self, p: (f64, f64)) {
        if self.points.covers(p.0, p.1) {
            let i = self.points.row(p.1) * self.points.cols + self.points.col(p.0);
            self.points.cells[i].push(p);
        }
    }

    /// A line to keep clear of where possible, as the points a label's
    /// region is tested at: every 3 pixels from p to q (at most 400).
    pub(super) fn line(&mut self, p: (f64, f64), q: (f64, f64)) {
        let steps = ((q.0 - p.0).hypot(q.1 - p.1) / 3.0)
            .ceil()
            .clamp(1.0, 400.0) as usize;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let s = (p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1));
            if self.lines.covers(s.0, s.1) {
                let i = self.lines.row(s.1) * self.lines.cols + self.lines.col(s.0);
                self.lines.cells[i].push(s);
            }
        }
    }

    /// A label placed at `b`.
    pub(super) fn label(&mut self, b: Rect) {
        let cells: Vec<usize> = self.boxes.meeting(b).map(|(i, _)| i).collect();
        for i in cells {
            self.boxes.cells[i].push(b);
        }
    }

    /// Whether a label at `b` covers no placed label, and no point or (when
    /// `strict`) line sample within 3 pixels of it.
    pub(super) fn is_free(&self, b: Rect, strict: bool) -> bool {
        let hits_box = self
            .boxes
            .meeting(b)
            .any(|(i, _)| self.boxes.cells[i].iter().any(|o| overlap(b, *o)));
        let near = (b.0 - PAD, b.1 - PAD, b.2 + PAD, b.3 + PAD);
        !(hits_box || hits(&self.points, near) || (strict && hits(&self.lines, near)))
    }
}

/// Whether two boxes overlap (touching edges do not).
fn overlap(b: Rect, o: Rect) -> bool {
    b.0 < o.2 && o.0 < b.2 && b.1 < o.3 && o.1 < b.3
}

/// Whether a point lies strictly inside `r`. A cell wholly inside `r`
/// answers by holding anything; only the cells on its edge are searched.
fn hits(cells: &Cells<(f64, f64)>, r: Rect) -> bool {
    let inside = |p: &(f64, f64)| p.0 > r.0 && p.0 < r.2 && p.1 > r.1 && p.1 < r.3;
    cells
        .meeting(r)
        .any(|(i, whole)| whole && !cells.cells[i].is_empty())
        || cells
            .meeting(r)
            .any(|(i, whole)| !whole && cells.cells[i].iter().any(inside))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_lines_and_labels_are_found_near_a_place() {
        let mut c = Clear::new((0.0, 0.0, 560.0, 480.0));
        c.point((100.0, 100.0));
        assert!(!c.is_free((90.0, 90.0, 110.0, 110.0), false));
        // 3 pixels of room around a label: a point 2.5 away is too near,
        // one 3.5 away is not.
        assert!(!c.is_free((102.5, 90.0, 130.0, 110.0), false));
        assert!(c.is_free((103.5, 90.0, 130.0, 110.0), false));
        c.line((200.0, 0.0), (200.0, 400.0));
        assert!(!c.is_free((190.0, 50.0, 210.0, 60.0), true));
        assert!(c.is_free((190.0, 50.0, 210.0, 60.0), false));
        c.label((300.0, 300.0, 340.0, 315.0));
        assert!(!c.is_free((330.0, 310.0, 360.0, 325.0), false));
        // Touching edges do not overlap.
        assert!(c.is_free((340.0, 300.0, 360.0, 315.0), false));
        // Points outside the panel are never near a label inside it.
        c.point((-1e9, f64::NAN));
        assert!(c.is_free((0.0, 0.0, 20.0, 20.0), true));
    }

    /// The index answers as testing every mark would (the layout before
    /// the index), on scattered points, lines and labels.
    #[test]
    fn the_index_agrees_with_testing_every_mark() {
        let mut seed = 7u64;
        let mut next = move |scale: f64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * scale
        };
        let mut c = Clear::new((560.0, 0.0, 1120.0, 480.0));
        let (mut points, mut lines, mut boxes) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..300 {
            let p = (500.0 + next(700.0), next(560.0) - 40.0);
            c.point(p);
            points.push(p);
        }
        for _ in 0..60 {
            let p = (540.0 + next(600.0), next(500.0) - 10.0);
            let q = (p.0 + next(200.0) - 100.0, p.1 + next(200.0) - 100.0);
            c.line(p, q);
            lines.push((p, q));
        }
        let mut agreed = (0, 0);
        for k in 0..3000 {
            let b = (560.0 + next(540.0), next(460.0), 0.0, 0.0);
            let b = (b.0, b.1, b.0 + 5.0 + next(60.0), b.1 + 15.0);
            // Labels lie inside the panel (the layout asks that first).
            if b.0 < 562.0 || b.2 > 1118.0 || b.1 < 2.0 || b.3 > 478.0 {
                continue;
            }
            let strict = k % 2 == 0;
            let near =
                |x: f64, y: f64| x > b.0 - 3.0 && x < b.2 + 3.0 && y > b.1 - 3.0 && y < b.3 + 3.0;
            let crosses = |p: (f64, f64), q: (f64, f64)| {
                let steps = ((q.0 - p.0).hypot(q.1 - p.1) / 3.0)
                    .ceil()
                    .clamp(1.0, 400.0) as usize;
                (0..=steps).any(|k| {
                    let t = k as f64 / steps as f64;
                    near(p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1))
                })
            };
            let brute = !(boxes.iter().any(|o| overlap(b, *o))
                || points.iter().any(|p| near(p.0, p.1))
                || (strict && lines.iter().any(|&(p, q)| crosses(p, q))));
            assert_eq!(c.is_free(b, strict), brute, "{b:?} strict {strict}");
            agreed.0 += usize::from(brute);
            agreed.1 += 1;
            if brute && k % 3 == 0 {
                c.label(b);
                boxes.push(b);
            }
        }
        // Both answers occur.
        assert!(agreed.0 > 50 && agreed.0 < agreed.1 - 50, "{agreed:?}");
    }
}
