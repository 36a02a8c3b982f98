//! A map keyed by raw handles for the few objects one recording or submission
//! names: inline and searched in order while small, so a frame's tables allocate and
//! hash nothing; indexed by a hash table once it grows past [`LINEAR`], so a
//! recording that names thousands of images stays linear in them.

use super::HashMap;
use smallvec::SmallVec;

/// Entries searched in order before the map builds its index.
const LINEAR: usize = 16;

/// A map from raw handles to `V`, in insertion order.
#[derive(Clone)]
pub(crate) struct SmallMap<V> {
    items: SmallVec<[(u64, V); 2]>,
    /// Each key's place in `items`, once there are more than [`LINEAR`] (boxed:
    /// the map stays small where it is moved with its owner).
    index: Option<Box<HashMap<u64, usize>>>,
}

impl<V> Default for SmallMap<V> {
    fn default() -> Self {
        SmallMap {
            items: SmallVec::new(),
            index: None,
        }
    }
}

impl<V: core::fmt::Debug> core::fmt::Debug for SmallMap<V> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_map().entries(self.iter()).finish()
    }
}

impl<V> SmallMap<V> {
    fn position(&self, key: u64) -> Option<usize> {
        match &self.index {
            Some(index) => index.get(&key).copied(),
            None => self.items.iter().position(|(k, _)| *k == key),
        }
    }

    /// The value of `key`.
    pub(crate) fn get(&self, key: u64) -> Option<&V> {
        let i = self.position(key)?;
        Some(&self.items[i].1)
    }

    /// The value of `key`, to change.
    pub(crate) fn get_mut(&mut self, key: u64) -> Option<&mut V> {
        let i = self.position(key)?;
        Some(&mut self.items[i].1)
    }

    /// The value of `key`, made by `make` if there is none (no entry is added when
    /// `make` returns `None`).
    pub(crate) fn get_or_try_insert(
        &mut self,
        key: u64,
        make: impl FnOnce() -> Option<V>,
    ) -> Option<&mut V> {
        let i = match self.position(key) {
            Some(i) => i,
            None => {
                self.items.push((key, make()?));
                let i = self.items.len() - 1;
                match &mut self.index {
                    Some(index) => {
                        index.insert(key, i);
                    }
                    None if self.items.len() > LINEAR => {
                        let index = self.items.iter().enumerate();
                        self.index = Some(Box::new(index.map(|(i, (k, _))| (*k, i)).collect()));
                    }
                    None => {}
                }
                i
            }
        };
        Some(&mut self.items[i].1)
    }

    /// The value of `key`, made by `make` if there is none.
    pub(crate) fn get_or_insert_with(&mut self, key: u64, make: impl FnOnce() -> V) -> &mut V {
        match self.get_or_try_insert(key, || Some(make())) {
            Some(v) => v,
            None => unreachable!("`make` always makes a value"),
        }
    }

    /// Every entry, in insertion order.
    pub(crate) fn iter(&self) -> impl Iterator<Item = (&u64, &V)> {
        self.items.iter().map(|(k, v)| (k, v))
    }

    /// Every value, to change, in insertion order.
    pub(crate) fn values_mut(&mut self) -> impl Iterator<Item = &mut V> {
        self.items.iter_mut().map(|(_, v)| v)
    }

    /// Whether there is no entry.
    pub(crate) fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// How many entries there are.
    pub(crate) fn len(&self) -> usize {
        self.items.len()
    }

    /// Keeps the entries `keep` says to, in order.
    pub(crate) fn retain(&mut self, mut keep: impl FnMut(u64, &mut V) -> bool) {
        self.items.retain(|(k, v)| keep(*k, v));
        self.reindex();
    }

    /// Removes every entry, keeping the inline part's or the heap's allocation.
    pub(crate) fn clear(&mut self) {
        self.items.clear();
        self.index = None;
    }

    /// Removes every entry, handing each out.
    pub(crate) fn drain(&mut self) -> impl Iterator<Item = (u64, V)> + '_ {
        self.index = None;
        self.items.drain(..)
    }

    /// The index again after entries moved: none while the map is small.
    fn reindex(&mut self) {
        self.index = (self.items.len() > LINEAR).then(|| {
            let index = self.items.iter().enumerate();
            Box::new(index.map(|(i, (k, _))| (*k, i)).collect())
        });
    }
}

impl<V> IntoIterator for SmallMap<V> {
    type Item = (u64, V);
    type IntoIter = smallvec::IntoIter<[(u64, V); 2]>;
    fn into_iter(self) -> Self::IntoIter {
        self.items.into_iter()
    }
}

impl<'a, V> IntoIterator for &'a SmallMap<V> {
    type Item = (&'a u64, &'a V);
    type IntoIter =
        core::iter::Map<core::slice::Iter<'a, (u64, V)>, fn(&'a (u64, V)) -> (&'a u64, &'a V)>;
    fn into_iter(self) -> Self::IntoIter {
        self.items.iter().map(|(k, v)| (k, v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Past the linear part the index finds every key, and insertion order holds.
    #[test]
    fn finds_every_key_before_and_after_the_index() {
        let mut map = SmallMap::default();
        for k in 0..100u64 {
            *map.get_or_insert_with(k * 7, || 0) += k;
            for j in 0..=k {
                assert_eq!(map.get(j * 7), Some(&j), "key {} after {k}", j * 7);
            }
            assert_eq!(map.get(k * 7 + 1), None);
        }
        assert!(map.iter().map(|(k, _)| *k).eq((0..100).map(|k| k * 7)));
        assert_eq!(map.get_or_try_insert(5, || None), None);
        assert_eq!(map.get(5), None);
        // Dropping entries moves the rest: the index follows, and goes when small.
        map.retain(|k, _| k % 2 == 0);
        assert_eq!(map.len(), 50);
        for k in 0..100u64 {
            let want = (k % 2 == 0).then_some(k);
            assert_eq!(map.get(k * 7).copied(), want, "key {}", k * 7);
        }
        // Keys 0, 14, 28, 42 and 56 are left: no index.
        map.retain(|k, _| k < 70);
        assert_eq!(map.len(), 5);
        assert!(map.index.is_none());
        assert_eq!(map.get_mut(56).copied(), Some(8));
    }
}
