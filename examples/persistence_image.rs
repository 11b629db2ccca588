//! The persistence diagram of a `.npy` image, timed stage by stage:
//! `cargo run --release --example persistence_image -- IMAGE.npy [T|V] [P]`.
use std::time::Instant;

use gmap_homology::persistence::{CubicalFiltration, CubicalOptions};
use gmap_ops::import::image::{Image, Order};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = args.get(1).expect("usage: persistence_image IMAGE.npy [T|V] [P]");
    let opts = CubicalOptions {
        construction: args.get(2).map_or("T", |s| s.as_str()).parse().expect("T or V"),
        field: args.get(3).map_or(2, |p| p.parse().expect("a prime")),
        ..CubicalOptions::default()
    };
    let t = Instant::now();
    let img = Image::read(std::path::Path::new(path)).expect("an image");
    let values: Vec<f64> = (0..img.len()).map(|i| img.value(i)).collect();
    let mut shape = img.shape().to_vec();
    if img.order() == Order::Fortran {
        shape.reverse();
    }
    let read = t.elapsed();
    let f = CubicalFiltration::new(&shape, &values, &opts).expect("a filtration");
    let built = t.elapsed();
    let d = f.diagram(&opts).expect("a diagram");
    let done = t.elapsed();
    let mut count = vec![0usize; shape.len() + 1];
    for p in &d.pairs {
        count[p.dim] += 1;
    }
    println!("pairs per dimension {count:?}; read {read:?}, values {:?}, diagram {:?}", built - read, done - built);
}
