// The synthetic whole-globe DEM of the viewer tests (make_global_dem.mjs writes it): heights in
// metres as a smooth function of the position on the sphere (x, y, z), so seamless across the
// antimeridian and at the poles: "continents" rising to about 4,500 m between "oceans" down to
// about -4,000 m. The tests use it as the oracle of the heights drawn.
const DEG = Math.PI / 180;

export function demHeight(lonDeg, latDeg) {
  const lon = lonDeg * DEG, lat = latDeg * DEG;
  const x = Math.cos(lat) * Math.cos(lon), y = Math.cos(lat) * Math.sin(lon), z = Math.sin(lat);
  const f = 0.9 * Math.sin(2.1 * x + 0.4) * Math.cos(1.7 * y - 0.3) + 0.5 * Math.sin(3.3 * z + 1.9 * x)
    + 0.3 * Math.cos(5.2 * y + 4.1 * z) + 0.12 * Math.sin(11 * x - 9 * z + 7 * y) - 0.15;
  return f > 0 ? 4500 * Math.tanh(1.6 * f) : 4000 * Math.tanh(2 * f);
}
