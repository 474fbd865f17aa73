fn main() {
    println!("chasles");
}
