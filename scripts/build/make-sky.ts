// Paints the default sky cube into public/sky/{px,nx,py,ny,pz,nz}.png. The sun sits where
// the default sunElevation/sunAzimuth parameters put the specular highlight.
import { mkdirSync, writeFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import { CUBE_FACES, SkyPainter } from '../../src/sim/optics/skyPainter';
import { sunDirection } from '../../src/sim/optics/sun';
import { paramDefs } from '../../src/sim/params/params';

const size = Number(process.argv[2] ?? 256);
const painter = new SkyPainter(sunDirection(paramDefs.sunElevation.default, paramDefs.sunAzimuth.default));
mkdirSync('public/sky', { recursive: true });
for (const face of CUBE_FACES) {
  const png = new PNG({ width: size, height: size });
  png.data = Buffer.from(painter.paintFace(face, size));
  writeFileSync(`public/sky/${face}.png`, PNG.sync.write(png, { colorType: 2 }));
  console.log(`public/sky/${face}.png`);
}
