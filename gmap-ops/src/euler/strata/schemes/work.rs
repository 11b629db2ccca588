//! The checks and edits every rule of the catalogue shares: its refusals, built from the
//! rule's precondition in words ([`Work::refuse`]), the expectations on strata and
//! components a rule states, and the edits that kill a stratum, split a component or extend
//! a frontier.

use super::*;

impl Work<'_> {
    /// The refusal of this rule's precondition, for the reason `why`.
    pub(super) fn refuse(&self, why: impl Into<String>) -> StrataError {
        StrataError::Precondition { op: self.name, requires: self.requires, why: why.into() }
    }

    pub(super) fn need<T>(&self, x: Option<T>, what: &'static str) -> Result<T, StrataError> {
        x.ok_or(StrataError::Missing { op: self.name, what })
    }

    /// The stratum argument `x`, which must be live.
    pub(super) fn stratum(&self, x: Option<usize>, what: &'static str) -> Result<usize, StrataError> {
        let s = self.need(x, what)?;
        self.o.stratum(s).map(|_| s)
    }

    pub(super) fn expect_dim(&self, s: usize, dim: usize) -> Result<(), StrataError> {
        let st = self.o.stratum(s)?;
        if st.dim != dim {
            return Err(self.refuse(format!("stratum {s} is {}-dimensional, not {dim}-dimensional", st.dim)));
        }
        Ok(())
    }

    pub(super) fn expect_state(&self, s: usize, complete: bool) -> Result<(), StrataError> {
        if self.o.stratum(s)?.complete != complete {
            return Err(self.refuse(format!("stratum {s} is not {}", state(complete))));
        }
        Ok(())
    }

    pub(super) fn expect_ball(&self, s: usize) -> Result<(), StrataError> {
        if !self.o.stratum(s)?.is_ball() {
            return Err(self.refuse(format!("stratum {s} has holes (it must be a ball)")));
        }
        Ok(())
    }

    /// Stratum `s` has `count` k-holes for `k = top` and none other.
    pub(super) fn expect_only_hole(&self, s: usize, top: usize, why: &str) -> Result<(), StrataError> {
        if self.o.strata[s].holes.iter().enumerate().any(|(k, &h)| h != if k == top { 1 } else { 0 }) {
            return Err(self.refuse(format!("stratum {s} {why}")));
        }
        Ok(())
    }

    pub(super) fn expect_component_state(&self, c: usize, complete: bool) -> Result<(), StrataError> {
        if self.o.component(c)?.complete != complete {
            return Err(self.refuse(format!("component {c} is not {}", state(complete))));
        }
        Ok(())
    }

    pub(super) fn expect_component_dim(&self, c: usize, n: usize) -> Result<(), StrataError> {
        if self.o.component_dim(c) != n {
            return Err(self.refuse(format!("component {c} is not {n}-dimensional")));
        }
        Ok(())
    }

    pub(super) fn expect_no_global_holes(&self, c: usize, why: &str) -> Result<(), StrataError> {
        if self.o.components[c].holes.iter().any(|&h| h != 0) {
            return Err(self.refuse(format!("component {c} {why}")));
        }
        Ok(())
    }

    /// The strata `strata` lie in the components `comps`, below dimension `below`.
    pub(super) fn expect_in(&self, strata: &[usize], comps: &[usize], below: usize) -> Result<(), StrataError> {
        for &b in strata {
            let st = self.o.stratum(b)?;
            if !comps.contains(&st.component) {
                return Err(self.refuse(format!("stratum {b} is not in component {comps:?}")));
            }
            if st.dim >= below {
                return Err(self.refuse(format!("stratum {b} is not of dimension below {below}")));
            }
        }
        Ok(())
    }

    pub(super) fn expect_frontier_of(&self, strata: &[usize], s: usize) -> Result<(), StrataError> {
        for &b in strata {
            self.o.stratum(b)?;
            if !self.o.strata[s].frontier.contains(&b) {
                return Err(self.refuse(format!("stratum {b} is not in the frontier of stratum {s}")));
            }
        }
        Ok(())
    }

    /// The fillers `on` are live strata below dimension `below`.
    pub(super) fn expect_fillers(&self, on: &[usize], below: usize) -> Result<(), StrataError> {
        for &b in on {
            if self.o.stratum(b)?.dim >= below {
                return Err(self.refuse(format!("stratum {b} is not of dimension below {below}")));
            }
        }
        Ok(())
    }

    /// t bounds only `allowed` and strata above them.
    pub(super) fn expect_bounds_only(&self, t: usize, allowed: &[usize]) -> Result<(), StrataError> {
        for r in self.o.bounded_by(t) {
            if allowed.contains(&r) {
                continue;
            }
            if !allowed.iter().any(|a| self.o.strata[r].frontier.contains(a)) {
                return Err(self.refuse(format!("stratum {t} also bounds stratum {r}")));
            }
        }
        Ok(())
    }

    /// Removes stratum `s`, which must bound nothing.
    pub(super) fn kill(&mut self, s: usize) -> Result<(), StrataError> {
        if let Some(&r) = self.o.bounded_by(s).first() {
            return Err(self.refuse(format!("stratum {s} bounds stratum {r}; make {r} boundary-incomplete first")));
        }
        self.o.strata[s].alive = false;
        Ok(())
    }

    /// Splits component `c`: the strata `moved` go to a new component with the same state,
    /// which takes the global holes `holes` from `c`. With `check_frontiers`, no frontier
    /// may join the two parts.
    pub(super) fn split_component(
        &mut self,
        c: usize,
        moved: &[usize],
        holes: &[(usize, i64)],
        check_frontiers: bool,
    ) -> Result<usize, StrataError> {
        let all = self.o.strata_of(c);
        if moved.is_empty() || moved.iter().any(|m| !all.contains(m)) {
            return Err(self.refuse(format!("the strata that move ({moved:?}) must be some strata of component {c}")));
        }
        if check_frontiers {
            for &s in &all {
                let here = moved.contains(&s);
                for &b in &self.o.strata[s].frontier {
                    if self.o.strata[b].component == c && moved.contains(&b) != here {
                        return Err(self.refuse(format!("stratum {s} is bounded by stratum {b} across the split")));
                    }
                }
            }
        }
        let nc = self.o.new_component(self.o.components[c].complete);
        for &m in moved {
            self.o.strata[m].component = nc;
        }
        for &(k, h) in holes {
            self.o.add_global_hole(c, k, -h)?;
            self.o.add_global_hole(nc, k, h)?;
        }
        Ok(nc)
    }

    /// Adds the fillers `on` to the frontier of `s`.
    pub(super) fn add_to_frontier(&mut self, s: usize, on: &[usize]) {
        for &b in on {
            if !self.o.strata[s].frontier.contains(&b) {
                self.o.strata[s].frontier.push(b);
            }
        }
    }
}
