/**
 * What each gallery card says: one sentence in a player's words, what you can do on the page (no
 * formulas, no engine terms), by game folder. A page missing here shows the first line of its
 * game.json summary.
 */
export const CARD_LINES: Readonly<Record<string, string>> = {
  catapult: 'Pull back the catapult and let fly: smash castles of wood, glass and stone in as few shots as you can.',
  'wrecking-ball': 'Tap a tower, a wall or a stack of planks and the crane swings its wrecking ball through it.',
  'black-hole': 'Steer a little ship to the finish line without getting swallowed by black holes.',
  fireworks: 'Light every lantern in the night sky with as few fireworks as you can: tap to launch, hold for a bigger burst.',
  submarine: 'Dive, trim and steer a submarine to every beacon on the sea floor.',
  'flight-simulator': 'Fly a jet over the hills and through the rings without stalling.',
  'bouncing-balls': 'Throw balls through a hoop that moves after every basket: how many can you score in 60 seconds?',
  'rotating-cube':
    'Roll a cube onto five glowing pads, the right face up, in as few moves as you can. Then steer a spinning cube onto target spins, and keep a box in the band while it flips 10 times in 20 s.',
  'solar-system': 'Launch a probe from the Earth to the planets: aim, pick your moment, then steer it there.',
  'lab-projectile-drag': 'Fire a ball off a cliff with and without air resistance and see where it lands.',
  'lab-orbits': 'Flick planets into orbit around a sun and watch their paths.',
  'lab-integrators': 'Race seven ways of simulating the same orbit and see which ones drift off course.',
  'lab-spring-chain': 'Pull a chain of springy weights and let it bounce.',
  'lab-bungee': 'Drop a jumper off a bridge on a bungee cord: how close to the river do they get?',
  'lab-pendulum': 'Swing a pendulum, big or small, and time its beat.',
  // Two toys without a goal to win, listed here with what to try (a score or a finish line for a box
  // of balls or the Moon's orbit would be made up): each line says what to explore.
  'earth-moon': 'Speed up time and follow the Moon round the Earth: see the Earth wobble round the point they both circle.',
  'balls-3d': 'Throw balls into a glass box of hundreds more: turn gravity and bounce up or down and watch the pile settle.',
  'lab-floating': 'Drop balls and a box into water and see which float, which sink and how deep they ride.',
  'lab-balloon-parachute': 'Open a parachute mid-fall, and let a balloon rise until the thin air stops it.',
  'lab-electric-field': 'Place charges, see their field lines and let a test charge fly.',
  'lab-cyclotron': 'Send a charged particle into a magnetic field and watch it loop.',
  'lab-rocket': 'Launch a rocket and watch it climb as it burns its fuel.',
  'lab-joints': 'Swing a pendulum, rattle a chain, drive a little car over bumps and throw a ragdoll.',
  'lab-rigid-bodies': 'Tilt a board until the boxes tip or slide, and drop crates on everything.',
  'lab-newtons-cradle': "Lift one or more balls of Newton's cradle and let go: as many fly off the other end.",
  'lab-rope': 'Cut the ropes at the right moment to drop the ball in the basket, catching the stars on the way.',
  'lab-cloth': 'Cut shapes out of a sheet flapping on the washing line, or pull it until it tears.',
  'lab-molecules': 'A box of bouncing gas molecules: watch their speeds spread out as they collide.',
  'lab-rigid-3d': 'Topple a ring of 100 dominoes, stack boxes and spin a top in 3D.',
  'lab-galaxy': 'A galaxy of 100,000 stars swirling around its heavy core.',
  'lab-wormhole': 'Stars fall into a black hole and shoot back out of a white hole.',
  'lab-splash': 'Rain splashing into a pool; click to drop your own.',
  'lab-smoke': 'Smoke rising from a chimney and drifting in the wind; change the wind.',
  'lab-fire': 'A crackling fire of flames, sparks and smoke; turn it up or down.',
  'lab-sparks': 'A grinder throwing showers of sparks that bounce off the floor.',
  'lab-attractors': 'Place attractors and watch swarms of particles swirl around them.',
};

/** The section a registry category is listed under, with a line under its heading. */
export const SECTIONS: Readonly<Record<string, { title: string; line: string }>> = {
  Games: { title: 'Games', line: 'Play them with a mouse, the keys or a finger.' },
  Labs: { title: 'Physics playground', line: 'Small experiments: poke them and see what happens.' },
};
