//! Where a label or a legend goes, for the line charts and the heat maps alike: the first of its
//! candidate boxes, in the order the caller prefers them, that costs the least (covers the
//! fewest curve pixels, or leaves the plotting area or overlaps what is already drawn).

/// A pixel rectangle: (left, top, right, bottom).
pub type Rect = (i32, i32, i32, i32);

/// Whether two rectangles share any pixel area.
pub fn overlaps(a: Rect, b: Rect) -> bool {
    a.0 < b.2 && b.0 < a.2 && a.1 < b.3 && b.1 < a.3
}

/// Whether `a` lies within `area`.
pub fn inside(a: Rect, area: Rect) -> bool {
    a.0 >= area.0 && a.1 >= area.1 && a.2 <= area.2 && a.3 <= area.3
}

/// The first of `candidates` with the least `cost`, with that cost (`None` when there is no
/// candidate). A candidate of cost 0 ends the search: none can do better.
pub fn first_least<T: Copy>(candidates: impl IntoIterator<Item = T>, cost: impl Fn(T) -> usize) -> Option<(T, usize)> {
    let mut best: Option<(T, usize)> = None;
    for c in candidates {
        let n = cost(c);
        if best.is_none_or(|(_, b)| n < b) {
            best = Some((c, n));
            if n == 0 {
                break;
            }
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_of_the_cheapest_wins() {
        assert_eq!(first_least([3, 1, 2, 1], |c| c), Some((1, 1)));
        assert_eq!(first_least([(0, 2), (1, 0), (2, 0)], |c| c.1), Some(((1, 0), 0)));
        assert_eq!(first_least(Vec::<u8>::new(), |_| 0), None);
        let area = (0, 0, 100, 100);
        assert!(inside((10, 10, 20, 20), area) && !inside((90, 90, 110, 95), area));
        assert!(overlaps((0, 0, 10, 10), (5, 5, 15, 15)) && !overlaps((0, 0, 10, 10), (10, 0, 20, 10)));
    }
}
