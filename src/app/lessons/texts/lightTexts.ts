import type { LessonText } from './lessonText';
import { m } from './mathml';

/** The cards of the sky, reflection, Fresnel, the glint, the boat and the view from under the water. */
export const lightTexts: Record<string, LessonText> = {
  'sky-cube': {
    text: {
      en: 'The sky is a cube map: six square images, one per face of a cube around the camera. Here it is unfolded into a cross, seen from inside: the middle row is the horizon all round, from −x through −z (where the default camera looks) to +x and +z, with +y, the zenith, above and −y below. A unit direction d̂ is enough to look it up: the GPU picks the face whose axis d̂ points along most, and the texel. The cube keeps the square root s of each colour in 8 bits, so the shader squares what it reads. Move the sun and the six faces are painted again, not every frame.',
      es: 'El cielo es un cube map: seis imágenes cuadradas, una por cara de un cubo alrededor de la cámara. Aquí está desplegado en una cruz, visto desde dentro: la fila central es el horizonte entero, de −x pasando por −z (adonde mira la cámara por defecto) a +x y +z, con +y, el cenit, arriba y −y abajo. Basta una dirección unitaria d̂ para consultarlo: la GPU elige la cara hacia cuyo eje apunta más d̂, y el texel. El cubo guarda la raíz cuadrada s de cada color en 8 bits, así que el shader eleva al cuadrado lo que lee. Al mover el sol se vuelven a pintar las seis caras, no en cada fotograma.',
    },
    math: m(
      '<mi>s</mi><mo>=</mo><mtext>textureLod</mtext><mo>(</mo><mtext>sky</mtext><mo>,</mo><mover><mi>d</mi><mo>^</mo></mover><mo>,</mo><mn>0</mn><mo>)</mo><mo>,</mo><mspace width="0.6em"/><mtext>color</mtext><mo>=</mo><msup><mi>s</mi><mn>2</mn></msup>',
    ),
    choice: {
      en: 'The sky is painted, not computed from scattering in the air: a zenith-to-horizon gradient, painted clouds, and a sun disc drawn 0.99° in radius where the real one’s is 0.27°.',
      es: 'El cielo está pintado, no calculado por dispersión atmosférica: degradado del cenit al horizonte, nubes pintadas y un disco solar de 0,99° de radio; el real tiene 0,27°.',
    },
    question: {
      ask: {
        en: 'The sun stands at azimuth 20°. Set Sun azimuth to 200°: in which cell of the cross will its disc appear?',
        es: 'El sol está en el acimut 20°. Pon el acimut del sol en 200°: ¿en qué celda de la cruz aparecerá su disco?',
      },
      answer: {
        en: 'In the rightmost cell of the middle row, +z, behind the default camera. Azimuth counts clockwise from −z, so at 200° its (x, z) is along (−0.34, 0.94), and a direction shows in the face whose axis it is nearest. At 20° the disc sat in the −z cell, right of its centre.',
        es: 'En la celda derecha de la fila central, +z, detrás de la cámara por defecto. El acimut crece en sentido horario desde −z: a 200° su (x, z) va según (−0,34; 0,94), y una dirección aparece en la cara de cuyo eje está más cerca. A 20° el disco estaba en la celda −z, a la derecha del centro.',
      },
    },
    references: ['greene1986'],
  },
  reflection: {
    text: {
      en: 'A still sea is a mirror: with no swell, no ripples and roughness off, what you see is the cube map looked up along the reflected view ray. With v the unit vector from the surface to the eye and n the normal, the shader reflects −v, the ray’s own direction, into r. A ray that would point below the horizon is lifted onto it. The sky read along r, c_sky, is mixed with the water’s own colour, c_water, by the Fresnel reflectance F, which nears 1 at grazing angles: far off, the sea is almost all sky. Switch roughness on and the slopes the mesh does not show blur the reflected sky.',
      es: 'Un mar en calma es un espejo: sin oleaje, sin ondas y sin rugosidad, lo que se ve es el cube map consultado en la dirección del rayo de vista reflejado. Con v el vector unitario de la superficie hacia el ojo y n la normal, el shader refleja −v, la dirección del propio rayo, en r. Un rayo que apuntaría bajo el horizonte se levanta hasta él. El cielo leído en r, c_sky, se mezcla con el color propio del agua, c_water, según la reflectancia de Fresnel F, que tiende a 1 en incidencia rasante: a lo lejos, el mar es casi todo cielo. Activa la rugosidad y las pendientes que la malla no muestra desenfocan el cielo reflejado.',
    },
    math:
      m('<mi>r</mi><mo>=</mo><mo>−</mo><mi>v</mi><mo>+</mo><mn>2</mn><mo>(</mo><mi>v</mi><mo>·</mo><mi>n</mi><mo>)</mo><mi>n</mi>') +
      m(
        '<mi>c</mi><mo>=</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>F</mi><mo>)</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>+</mo><mi>F</mi><msub><mi>c</mi><mtext>sky</mtext></msub>',
      ),
    choice: {
      en: 'Lifting r onto the horizon is a choice: the sea reflects only the sky cube, never other waves, the boat or itself.',
      es: 'Levantar r hasta el horizonte es una elección: el mar solo refleja el cubo del cielo, nunca otras olas, el barco ni a sí mismo.',
    },
    question: {
      ask: {
        en: 'Switch Fresnel off. Will the sea near the camera get paler or darker, and the sea near the horizon?',
        es: 'Apaga Fresnel. ¿El mar cerca de la cámara se aclarará o se oscurecerá? ¿Y el mar cerca del horizonte?',
      },
      answer: {
        en: 'Off, the shader uses F = 0.5 at every angle. Near the camera, where the true F is well below one half, the sea turns paler, half sky; near the horizon, where F is close to 1, it darkens to half water. Switch Fresnel on again to compare.',
        es: 'Apagado, el shader usa F = 0,5 en todos los ángulos. Cerca de la cámara, donde la F real queda muy por debajo de un medio, el mar se aclara, mitad cielo; cerca del horizonte, donde F es casi 1, se oscurece hasta ser mitad agua. Vuelve a activar Fresnel para comparar.',
      },
    },
    references: ['blinnNewell1976', 'greene1986', 'hecht2017'],
  },
  fresnel: {
    text: {
      en: 'Water’s reflectance depends on the angle of incidence θi, from the normal: 2 % looking straight down, all at grazing incidence. Snell’s law gives the angle θt of the ray that enters, from n₁ = 1 (air) and n₂ = 1.333 (water); the Fresnel equations give the amplitude ratios r_s and r_p of the two polarisations, and unpolarised light reflects the mean of their squares, F. The CPU tabulates F once, 256 entries by cos θi, uploaded as a 256 × 1 float texture (WebGL2 has no 1D textures); the fragment shader reads two entries with texelFetch and interpolates by hand, since float textures are not always filterable. The plot shows that table.',
      es: 'La reflectancia del agua depende del ángulo de incidencia θi, desde la normal: un 2 % en vertical, toda en incidencia rasante. La ley de Snell da el ángulo θt del rayo que entra, con los índices n₁ = 1 (aire) y n₂ = 1,333 (agua); las ecuaciones de Fresnel dan los cocientes de amplitud r_s y r_p de las dos polarizaciones; la luz no polarizada refleja la media de sus cuadrados, F. La CPU tabula F una vez, 256 entradas por cos θi, como textura float de 256 × 1 (WebGL2 no tiene texturas 1D); el fragment shader lee dos con texelFetch e interpola a mano: las texturas float no siempre se filtran. El gráfico muestra esa tabla.',
    },
    math:
      m(
        '<msub><mi>n</mi><mn>1</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>i</mi></msub><mo>=</mo><msub><mi>n</mi><mn>2</mn></msub><mi>sin</mi><msub><mi>θ</mi><mi>t</mi></msub>',
      ) +
      m(
        '<mi>F</mi><mo>=</mo><mfrac><mrow><msubsup><mi>r</mi><mi>s</mi><mn>2</mn></msubsup><mo>+</mo><msubsup><mi>r</mi><mi>p</mi><mn>2</mn></msubsup></mrow><mn>2</mn></mfrac>',
      ),
    question: {
      ask: {
        en: 'Before reading the plot: at 60° from the vertical, is water’s reflectance nearer 6 %, 25 % or 50 %?',
        es: 'Antes de mirar el gráfico: a 60° de la vertical, ¿la reflectancia del agua está más cerca del 6 %, del 25 % o del 50 %?',
      },
      answer: {
        en: 'About 6 %: the curve stays low up to 60° (0.060 there) and climbs steeply only past 75°, reaching one half near 84° and 1 at 90°. That is why the near sea shows the water’s colour and the far sea the sky. Fresnel plot draws it.',
        es: 'Cerca del 6 %: la curva sigue baja hasta 60° (0,060 ahí) y solo sube con fuerza pasados 75°: llega a un medio cerca de 84° y a 1 en 90°. Por eso el mar cercano muestra el color del agua y el lejano el cielo. El gráfico de Fresnel lo dibuja.',
      },
    },
    references: ['hecht2017'],
  },
  'fresnel-schlick': {
    text: {
      en: 'Schlick’s approximation replaces the Fresnel equations by one power of the angle of incidence θ: the reflectance at normal incidence, R₀ = ((n − 1)/(n + 1))² = 0.0204 for water’s index n = 1.333, plus the rest, 1 − R₀, times (1 − cos θ)⁵. The plot draws both curves. They agree at 0° and at 90°, not between: the largest difference, 0.059, lies near 84°, where Schlick gives 0.574 and the exact table 0.515. The shader never uses Schlick. Here Fresnel is switched off, so the sea mixes sky and water with a constant F = 0.5 at every angle, the sun’s glint too: compare it with the previous lesson.',
      es: 'La aproximación de Schlick sustituye las ecuaciones de Fresnel por una potencia del ángulo de incidencia θ: la reflectancia en incidencia normal, R₀ = ((n − 1)/(n + 1))² = 0,0204 para el índice del agua n = 1,333, más el resto, 1 − R₀, por (1 − cos θ)⁵. El gráfico dibuja ambas curvas. Coinciden en 0° y en 90°, no entre medias: la mayor diferencia, 0,059, está cerca de 84°, donde Schlick da 0,574 y la tabla exacta 0,515. El shader nunca usa Schlick. Aquí Fresnel está apagado, así que el mar mezcla cielo y agua con una F constante de 0,5 en todos los ángulos, también en el destello del sol: compáralo con la lección anterior.',
    },
    math:
      m(
        '<mi>F</mi><mo>≈</mo><msub><mi>R</mi><mn>0</mn></msub><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><msub><mi>R</mi><mn>0</mn></msub><mo>)</mo><msup><mrow><mo>(</mo><mn>1</mn><mo>−</mo><mi>cos</mi><mi>θ</mi><mo>)</mo></mrow><mn>5</mn></msup>',
      ) +
      m(
        '<msub><mi>R</mi><mn>0</mn></msub><mo>=</mo><msup><mrow><mo>(</mo><mfrac><mrow><mi>n</mi><mo>−</mo><mn>1</mn></mrow><mrow><mi>n</mi><mo>+</mo><mn>1</mn></mrow></mfrac><mo>)</mo></mrow><mn>2</mn></msup><mo>=</mo><mn>0.0204</mn>',
      ),
    choice: {
      en: 'Fresnel off is a teaching switch: the constant F = 0.5 is no physical value; it shows what the angle dependence adds.',
      es: 'Fresnel apagado es un interruptor didáctico: la F constante de 0,5 no es un valor físico; muestra lo que añade la dependencia del ángulo.',
    },
    question: {
      ask: {
        en: 'Where will the two curves on the plot lie farthest apart: at normal incidence, at 60°, or near grazing?',
        es: '¿Dónde estarán más separadas las dos curvas del gráfico: en incidencia normal, a 60° o cerca de la incidencia rasante?',
      },
      answer: {
        en: 'Near grazing, at about 84°: Schlick lies 0.059 above the exact reflectance there (0.574 against 0.515). At 0° both give R₀ = 0.0204 and at 90° both give 1; at 60° they differ by less than 0.01. Fresnel plot shows both curves.',
        es: 'Cerca de la incidencia rasante, hacia 84°: ahí Schlick queda 0,059 por encima de la reflectancia exacta (0,574 frente a 0,515). En 0° ambas dan R₀ = 0,0204 y en 90° ambas dan 1; a 60° difieren en menos de 0,01. El gráfico de Fresnel muestra las dos curvas.',
      },
    },
    references: ['schlick1994', 'hecht2017'],
  },
  'sun-glint': {
    text: {
      en: 'The sun’s glitter is the sun seen in countless tilted facets. Cox and Munk photographed it from the air in 1951 and found the facets’ mean-square slope σ² = 0.003 + 0.00512 U, with U the wind speed in m/s 12.5 m above the sea (the Wind speed slider, 10 m up, is converted): raise the wind and the glitter widens. The shader reflects the sun through a Beckmann distribution of that σ², less the slopes the waves already draw. The sun is far brighter than a screen’s white, so each colour channel c, after exposure, goes through one tone curve f: below k = 0.6 it stays as it is, above it rolls off towards white instead of clipping.',
      es: 'El destello es el sol visto en incontables facetas inclinadas. Cox y Munk lo fotografiaron desde el aire en 1951: la pendiente cuadrática media de las facetas es σ² = 0,003 + 0,00512 U, con U el viento en m/s a 12,5 m sobre el mar (el control, a 10 m, se convierte): con más viento, el destello se ensancha. El shader refleja el sol con una distribución de Beckmann de esa σ², menos las pendientes que ya dibujan las olas. El sol brilla mucho más que el blanco de la pantalla: cada canal de color c, tras la exposición, pasa por una curva de tono f; bajo k = 0,6 no cambia, encima se acerca al blanco sin recortarse.',
    },
    math:
      m(
        '<msup><mi>σ</mi><mn>2</mn></msup><mo>=</mo><mn>0.003</mn><mo>+</mo><mn>5.12</mn><mo>·</mo><msup><mn>10</mn><mrow><mo>−</mo><mn>3</mn></mrow></msup><mi>U</mi>',
      ) +
      m(
        '<mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>c</mi><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>≤</mo><mi>k</mi><mo>;</mo><mspace width="0.6em"/><mi>f</mi><mo>(</mo><mi>c</mi><mo>)</mo><mo>=</mo><mi>k</mi><mo>+</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo><mo>(</mo><mn>1</mn><mo>−</mo><msup><mi>e</mi><mrow><mo>−</mo><mo>(</mo><mi>c</mi><mo>−</mo><mi>k</mi><mo>)</mo><mo>/</mo><mo>(</mo><mn>1</mn><mo>−</mo><mi>k</mi><mo>)</mo></mrow></msup><mo>)</mo><mspace width="0.3em"/><mtext>if</mtext><mspace width="0.3em"/><mi>c</mi><mo>&gt;</mo><mi>k</mi>',
      ),
    choice: {
      en: 'The tone curve’s knee k = 0.6 and its exponential shoulder are a display choice; Cox and Munk’s slopes are measured, Beckmann’s facets a model of them.',
      es: 'El codo k = 0,6 y el hombro exponencial de la curva de tono son una elección; las pendientes de Cox y Munk son medidas, y Beckmann, su modelo.',
    },
    question: {
      ask: {
        en: 'Raise Wind speed from 5 to 15 m/s: will the path of glitter get wider or narrower?',
        es: 'Sube la velocidad del viento de 5 a 15 m/s: ¿el camino de destellos se hará más ancho o más estrecho?',
      },
      answer: {
        en: 'Wider: Cox and Munk’s σ² grows from 0.029 to 0.081 (the wind taken to 12.5 m), so facets tilted farther from the mirror direction still send you the sun. The same sunlight spreads over more sea, so each part of the path is dimmer, though its core may stay white through the tone curve.',
        es: 'Más ancho: la σ² de Cox y Munk pasa de 0,029 a 0,081 (el viento llevado a 12,5 m), así que facetas más inclinadas respecto del espejo aún te envían el sol. La misma luz cubre más mar: cada parte del camino es más tenue, aunque su núcleo puede seguir blanco tras la curva de tono.',
      },
    },
    references: ['coxMunk1954', 'bruneton2010', 'walter2007', 'reinhard2002'],
  },
  'boat-twin': {
    text: {
      en: 'The GPU moves the vertices, but reading its heights back every frame would make the page wait for it. So the displacement function M is written twice: in GLSL for the picture and in TypeScript for the CPU. The phases φ₁…φ₄ are computed once a frame on the CPU, in double precision, and handed to both; the ripples come from the same heightmaps. A browser test reads the shader’s heights back from the GPU and finds them within 0.03 mm of this twin at the default parameters. The boat floats on the twin’s heights, taken at the five points marked on its hull. In the swell, A is the amplitude, k the wavenumber, (u, v) the axes turned by 37°.',
      es: 'La GPU mueve los vértices, pero leer sus alturas en cada fotograma haría esperar a la página. Por eso la función de desplazamiento M se escribe dos veces: en GLSL para la imagen y en TypeScript para la CPU. La CPU calcula las fases φ₁…φ₄ una vez por fotograma, en doble precisión, para ambas; las ondas salen de los mismos mapas de alturas. Una prueba lee de la GPU las alturas del shader: difieren menos de 0,03 mm de este gemelo con los parámetros por defecto. El barco flota sobre las alturas del gemelo, en los cinco puntos marcados en su casco. En el oleaje, A es la amplitud, k el número de onda, (u, v) los ejes girados 37°.',
    },
    math:
      m(
        '<msub><mi>h</mi><mtext>swell</mtext></msub><mo>=</mo><mi>A</mi><mo>[</mo><mi>sin</mi><mo>(</mo><mi>k</mi><mi>x</mi><mo>+</mo><msub><mi>φ</mi><mn>1</mn></msub><mo>)</mo><mi>cos</mi><mo>(</mo><mi>k</mi><mi>z</mi><mo>+</mo><msub><mi>φ</mi><mn>2</mn></msub><mo>)</mo><mo>+</mo><mn>0.45</mn><mspace width="0.1em"/><mi>sin</mi><mo>(</mo><mn>1.73</mn><mi>k</mi><mi>u</mi><mo>+</mo><msub><mi>φ</mi><mn>3</mn></msub><mo>)</mo><mi>cos</mi><mo>(</mo><mn>1.73</mn><mi>k</mi><mi>v</mi><mo>+</mo><msub><mi>φ</mi><mn>4</mn></msub><mo>)</mo><mo>]</mo>',
      ) +
      m(
        '<msub><mi>M</mi><mtext>CPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo><mo>≈</mo><msub><mi>M</mi><mtext>GPU</mtext></msub><mo>(</mo><mi>x</mi><mo>,</mo><mi>z</mi><mo>,</mo><mi>t</mi><mo>)</mo>',
      ),
    question: {
      ask: {
        en: 'Raise Float response time from 0.25 s to 2 s: how far can the boat fall behind the water it floats on?',
        es: 'Sube el tiempo de respuesta de la flotación de 0,25 s a 2 s: ¿cuánto puede quedarse atrás el barco respecto del agua en que flota?',
      },
      answer: {
        en: 'Not far: it follows more slowly, a critically damped spring with ω = 1/response, but its heave is held within 0.2 m of the twin’s height at the hull’s centre and its pitch and roll within 0.08 rad (4.6°) of the surface’s. It lags and smooths, but never sinks or flies.',
        es: 'Poco: sigue más despacio, como un resorte con amortiguamiento crítico de ω = 1/respuesta, pero su elevación se mantiene a menos de 0,2 m de la altura del gemelo en el centro del casco, y su cabeceo y balanceo a menos de 0,08 rad (4,6°) de los de la superficie. Se retrasa y suaviza, pero nunca se hunde ni vuela.',
      },
    },
  },
  'boat-pitch': {
    text: {
      en: 'The seed’s “Quiero mover el bote”: the boat samples the CPU twin at five points, marked on the hull: its centre, the bow and stern half a hull length L away, and both sides half a beam B away. The centre’s height gives the heave; the height difference from stern to bow over L gives the pitch θ, the difference from port to starboard over B the roll φ, divided by √(1 + tan²θ) so that on a tilted plane the hull’s up axis is exactly its normal. A critically damped follower then smooths all three, so the hull does not jitter on every ripple.',
      es: 'El “Quiero mover el bote” del informe: el barco muestrea el gemelo en CPU en cinco puntos, marcados en el casco: su centro, la proa y la popa a media eslora L, y ambos costados a media manga B. La altura del centro da la elevación; la diferencia de altura de popa a proa entre L da el cabeceo θ, y la de babor a estribor entre B, el balanceo φ, dividida por √(1 + tan²θ) para que sobre un plano inclinado el eje vertical del casco sea justo su normal. Después un seguidor con amortiguamiento crítico suaviza los tres, para que el casco no tiemble con cada onda.',
    },
    math:
      m(
        '<mi>θ</mi><mo>=</mo><mi>arctan</mi><mfrac><mrow><msub><mi>h</mi><mtext>bow</mtext></msub><mo>−</mo><msub><mi>h</mi><mtext>stern</mtext></msub></mrow><mi>L</mi></mfrac>',
      ) +
      m(
        '<mi>φ</mi><mo>=</mo><mi>arctan</mi><mfrac><mrow><msub><mi>h</mi><mtext>starboard</mtext></msub><mo>−</mo><msub><mi>h</mi><mtext>port</mtext></msub></mrow><mrow><mi>B</mi><msqrt><mn>1</mn><mo>+</mo><msup><mi>tan</mi><mn>2</mn></msup><mi>θ</mi></msqrt></mrow></mfrac>',
      ),
    choice: {
      en: 'The damped follower is a choice, not hydrostatics: the boat has no buoyancy, mass or natural period, and stays within 0.2 m and 4.6° of the surface’s pose.',
      es: 'El seguidor amortiguado es una elección, no hidrostática: el barco no tiene flotabilidad, masa ni periodo propio, y queda a menos de 0,2 m y 4,6° de la superficie.',
    },
    question: {
      ask: {
        en: 'Halve Swell amplitude, from 1.6 m to 0.8 m: will the boat’s largest pitch halve, shrink less, or shrink more?',
        es: 'Reduce a la mitad la amplitud del oleaje, de 1,6 m a 0,8 m: ¿el mayor cabeceo del barco se reducirá a la mitad, menos o más?',
      },
      answer: {
        en: 'About halve: the pitch is the arctangent of the bow-minus-stern height over L, and for slopes this small (under 0.35) the arctangent is nearly the slope itself, which is proportional to A. The ripples, which do not change, keep a small part of the motion.',
        es: 'Más o menos a la mitad: el cabeceo es el arcotangente de la diferencia de altura entre proa y popa dividida por L, y para pendientes tan pequeñas (menos de 0,35) el arcotangente es casi la pendiente misma, proporcional a A. Las ondas, que no cambian, conservan una pequeña parte del movimiento.',
      },
    },
  },
  'snell-window': {
    text: {
      en: 'Seen from below, the whole sky is squeezed into a circle overhead: Snell’s window. A ray leaving water (n_water = 1.333) for air (n_air = 1) bends away from the normal; beyond the critical angle θc = arcsin(1/1.333) = 48.6° it cannot leave at all: it is totally reflected, and you see the water’s own colour mirrored. So the sky’s whole hemisphere fits in a cone 97° across. Inside it the reflectance from below climbs from 2 % overhead to 1 at the rim, so the sky dims towards the edge. The rim moves with the waves, because each facet has its own normal.',
      es: 'Visto desde abajo, todo el cielo se comprime en un círculo sobre la cabeza: la ventana de Snell. Un rayo que pasa del agua (n_water = 1,333) al aire (n_air = 1) se aleja de la normal; más allá del ángulo crítico θc = arcsen(1/1,333) = 48,6° no puede salir: se refleja totalmente y se ve el color propio del agua reflejado. Así, todo el hemisferio del cielo cabe en un cono de 97°. Dentro, la reflectancia desde abajo sube del 2 % en la vertical a 1 en el borde, y el cielo se oscurece hacia él. El borde se mueve con las olas, porque cada faceta tiene su propia normal.',
    },
    math: m(
      '<msub><mi>θ</mi><mi>c</mi></msub><mo>=</mo><mi>arcsin</mi><mfrac><msub><mi>n</mi><mtext>air</mtext></msub><msub><mi>n</mi><mtext>water</mtext></msub></mfrac><mo>=</mo><mn>48.6</mn><mo>°</mo>',
    ),
    choice: {
      en: 'Outside the window, what the surface mirrors is the fog’s painted colour for that direction, not a true reflection of the sea bed or the boat.',
      es: 'Fuera de la ventana, lo que refleja la superficie es el color pintado de la niebla en esa dirección, no un reflejo real del fondo ni del barco.',
    },
    question: {
      ask: {
        en: 'Switch Fresnel off: will the rim of the window get sharper or softer?',
        es: 'Apaga Fresnel: ¿el borde de la ventana se hará más nítido o más suave?',
      },
      answer: {
        en: 'Sharper. Off, the shader shows all sky inside θc and all mirrored water outside: a step. On, the reflectance from below climbs steeply just before 48.6°, so the sky dims and fades into the mirrored water over the last few degrees.',
        es: 'Más nítido. Apagado, el shader muestra todo cielo dentro de θc y todo agua reflejada fuera: un escalón. Encendido, la reflectancia desde abajo sube con fuerza justo antes de 48,6°, así que el cielo se oscurece y se funde con el agua reflejada en los últimos grados.',
      },
    },
    references: ['hecht2017'],
  },
  'underwater-fog': {
    text: {
      en: 'Under the water, light is absorbed and scattered: red goes first, blue travels farthest. Pure water’s measured beam attenuation sets the ratios ε, 9.7 : 1 : 0.43 for red, green and blue; Water fog density σ is green’s attenuation per metre (0.035 is pure water, this view sets 0.06). The shader attenuates each channel by the Beer–Lambert law over the distance d travelled, and fills what was lost with the water’s own colour c_water, lighter looking up, darker looking down; c₀ is the colour behind the water. Then a Gaussian blur softens the whole picture, as the seed did when the camera dives.',
      es: 'Bajo el agua la luz se absorbe y se dispersa: el rojo desaparece antes y el azul llega más lejos. La atenuación medida del agua pura fija las proporciones ε, 9,7 : 1 : 0,43 para rojo, verde y azul; la densidad de niebla σ es la atenuación del verde por metro (0,035 es agua pura; esta vista pone 0,06). El shader atenúa cada canal con la ley de Beer–Lambert según la distancia recorrida d y rellena lo perdido con el color propio del agua c_water, más claro mirando hacia arriba y más oscuro hacia abajo; c₀ es el color detrás del agua. Después un desenfoque gaussiano suaviza toda la imagen, como hacía el informe al sumergirse.',
    },
    math:
      m('<mi>T</mi><mo>(</mo><mi>d</mi><mo>)</mo><mo>=</mo><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><mi>ε</mi><mi>d</mi></mrow></msup>') +
      m(
        '<mi>c</mi><mo>=</mo><msub><mi>c</mi><mn>0</mn></msub><mi>T</mi><mo>+</mo><msub><mi>c</mi><mtext>water</mtext></msub><mo>(</mo><mn>1</mn><mo>−</mo><mi>T</mi><mo>)</mo>',
      ),
    choice: {
      en: 'Only the ratios ε are measured; the water’s own colour, from 0.22 looking down to 1 looking up, and the blur are painted choices.',
      es: 'Solo las proporciones ε son medidas; el color propio del agua, de 0,22 mirando abajo a 1 mirando arriba, y el desenfoque son elecciones pintadas.',
    },
    question: {
      ask: {
        en: 'At this view’s density, 0.06 per metre, will things 10 m away look only dimmer, or also bluer-green?',
        es: 'Con la densidad de esta vista, 0,06 por metro, ¿lo que está a 10 m se verá solo más tenue o también más azul verdoso?',
      },
      answer: {
        en: 'Bluer-green: over 10 m red keeps 0.3 % of its light, green 55 % and blue 77 %. Halve Water fog density and the same loss of red takes 20 m.',
        es: 'Más azul verdoso: en 10 m el rojo conserva el 0,3 % de su luz, el verde el 55 % y el azul el 77 %. Reduce a la mitad la densidad de niebla y esa misma pérdida de rojo necesita 20 m.',
      },
    },
    references: ['popeFry1997', 'morel1974'],
  },
  caustics: {
    text: {
      en: 'Caustics are the bright net of light on the sea bed. Each wave is a small lens: sunlight refracted through it converges in some places and spreads in others. For every point of the bed the shader follows three rays from the corners of a 0.75 m patch of the surface, refracts them by Snell’s law, and compares the area A_bed their landing points span with the patch’s own area A_surface. A patch squeezed to half its area receives twice the light. Where rays cross, the gain would be infinite, so it is capped at 8; Caustics intensity s then mixes it with the flat light, 1.',
      es: 'Las cáusticas son la red brillante de luz en el fondo. Cada ola es una pequeña lente: la luz del sol refractada converge en unos sitios y se dispersa en otros. Para cada punto del fondo el shader sigue tres rayos desde las esquinas de un trozo de superficie de 0,75 m, los refracta con la ley de Snell y compara el área A_bed que abarcan sus puntos de llegada con el área propia del trozo, A_surface. Un trozo comprimido a la mitad de su área recibe el doble de luz. Donde los rayos se cruzan la ganancia sería infinita, así que se limita a 8; la intensidad de las cáusticas s la mezcla con la luz plana, 1.',
    },
    math:
      m(
        '<mtext>gain</mtext><mo>=</mo><mi>min</mi><mo>(</mo><mfrac><msub><mi>A</mi><mtext>surface</mtext></msub><msub><mi>A</mi><mtext>bed</mtext></msub></mfrac><mo>,</mo><mn>8</mn><mo>)</mo>',
      ) +
      m(
        '<mi>E</mi><mo>=</mo><mi>max</mi><mo>(</mo><mn>0</mn><mo>,</mo><mn>1</mn><mo>+</mo><mi>s</mi><mo>(</mo><mtext>gain</mtext><mo>−</mo><mn>1</mn><mo>)</mo><mo>)</mo>',
      ),
    choice: {
      en: 'The cap at 8 and an intensity above 1 are choices: a true caustic is unbounded on its fold lines, and intensity 2 or 3 exaggerates the contrast.',
      es: 'El límite de 8 y una intensidad mayor que 1 son elecciones: una cáustica real no tiene cota en sus pliegues, y una intensidad 2 o 3 exagera el contraste.',
    },
    question: {
      ask: {
        en: 'Set Caustics intensity to 0: will the bed go dark, keep its net, or turn evenly lit?',
        es: 'Pon la intensidad de las cáusticas en 0: ¿el fondo se oscurecerá, conservará su red o quedará iluminado por igual?',
      },
      answer: {
        en: 'Evenly lit: the shader mixes 1 and the gain by the intensity, so at 0 every point gets the sunlight a flat sea would send, still dimmed by the water above it. The bright net and the dim cells between it vanish together.',
        es: 'Iluminado por igual: el shader mezcla 1 y la ganancia según la intensidad, así que con 0 cada punto recibe la luz que enviaría un mar plano, atenuada aún por el agua de encima. La red brillante y las celdas tenues entre sus líneas desaparecen a la vez.',
      },
    },
    references: ['watt1990'],
  },
  'god-rays': {
    text: {
      en: 'God rays are shafts of sunlight made visible by the water. The shader marches N = 40 steps of length Δt along each line of sight, up to 60 m. At step i, at distance t_i and depth d_i, it reads S, the light the waves let through where that sunlight crossed the surface; dims it over its path down, d_i/μ with μ the cosine of the refracted sun’s zenith angle, and on to the eye, t_i, by extinction σε per channel; fades the shafts’ contrast over D = 30 m of depth; and scatters by σ and a phase p(θ), θ the angle from the sun’s direction. Each factor is exponential in t: each step multiplies by constants.',
      es: 'Los rayos de luz son haces de sol que el agua hace visibles. El shader avanza N = 40 pasos de longitud Δt por cada línea de visión, hasta 60 m. En el paso i, a distancia t_i y profundidad d_i, lee S, la luz que dejan pasar las olas donde ese sol cruzó la superficie; la atenúa bajando, d_i/μ con μ el coseno del ángulo cenital del sol refractado, y hasta el ojo, t_i, con la extinción σε de cada canal; desvanece el contraste de los haces en D = 30 m de profundidad; y dispersa según σ y una fase p(θ), θ el ángulo respecto del sol. Cada factor es exponencial en t: cada paso multiplica por constantes.',
    },
    math:
      m(
        '<mi>L</mi><mo>=</mo><mi>σ</mi><mspace width="0.1em"/><mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mspace width="0.1em"/><mi>Δ</mi><mi>t</mi><munderover><mo>∑</mo><mrow><mi>i</mi><mo>=</mo><mn>1</mn></mrow><mi>N</mi></munderover><mi>S</mi><mo>(</mo><msub><mi>s</mi><mi>i</mi></msub><mo>)</mo><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><msub><mi>d</mi><mi>i</mi></msub><mo>/</mo><mi>D</mi></mrow></msup><mspace width="0.1em"/><msup><mi>e</mi><mrow><mo>−</mo><mi>σ</mi><mi>ε</mi><mo>(</mo><msub><mi>t</mi><mi>i</mi></msub><mo>+</mo><msub><mi>d</mi><mi>i</mi></msub><mo>/</mo><mi>μ</mi><mo>)</mo></mrow></msup>',
      ) +
      m('<mi>p</mi><mo>(</mo><mi>θ</mi><mo>)</mo><mo>=</mo><mn>0.3</mn><mo>+</mo><mn>3</mn><msup><mi>cos</mi><mn>4</mn></msup><mi>θ</mi>'),
    choice: {
      en: 'S is a stand-in, the ripples’ height band-passed and cubed, not refraction; the phase p(θ), the 30 m fade and the gain are artistic.',
      es: 'S es un sustituto, la altura de las ondas filtrada en banda y al cubo, no refracción; la fase p(θ), el desvanecimiento en 30 m y la ganancia son artísticos.',
    },
    question: {
      ask: {
        en: 'Raise Water fog density from this view’s 0.035 to 0.3 per metre: more water to scatter light, so brighter shafts, or fainter ones?',
        es: 'Sube la densidad de niebla de 0,035, la de esta vista, a 0,3 por metro: más agua que dispersa la luz, ¿haces más brillantes o más tenues?',
      },
      answer: {
        en: 'Fainter, shorter and bluer. Each metre scatters more (the factor σ), but the sunlight must first cross some 12 m of water to the camera’s depth and then reach the eye: at 0.3 the green keeps about 3 % over those 12 m, the blue about a fifth.',
        es: 'Más tenues, más cortos y más azules. Cada metro dispersa más (el factor σ), pero la luz del sol debe cruzar antes unos 12 m de agua hasta la profundidad de la cámara y luego llegar al ojo: con 0,3 el verde conserva cerca del 3 % en esos 12 m, el azul alrededor de una quinta parte.',
      },
    },
    references: ['popeFry1997', 'morel1974'],
  },
};
