package io.concord.core.content;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/** The binary content codec: the same abstract content as SL, smaller, and as strict. */
class BinaryContentCodecTest {
    private static final int CASES = Integer.getInteger("concord.sl.cases", 5_000);
    private static final int INPUTS = Integer.getInteger("concord.sl.fuzz", 100_000);
    private static final long SEED = Long.getLong("concord.sl.seed", 33L);

    private final BinaryContentCodec binary = new BinaryContentCodec();
    private final SlCodec sl = new SlCodec();
    private final BeanOntology ontology = BookShop.ontology();
    private final ContentManager manager = new ContentManager().register(binary).register(ontology);

    @Test
    void randomContentComesBackTheSameAndSmallerThanSl() throws Exception {
        ContentGenerator g = new ContentGenerator(SEED);
        long binaryBytes = 0;
        long slChars = 0;
        for (int i = 0; i < CASES; i++) {
            Object content = g.contentElement();
            AbsObject abs = ontology.toAbs(content);
            byte[] bytes = binary.write(List.of(abs));
            List<AbsObject> back = binary.read(bytes);
            assertEquals(List.of(abs), back, "case " + i);
            AclMessage msg = new AclMessage(Performative.INFORM).setLanguage(BinaryContentCodec.LANGUAGE).setOntology("book-shop");
            msg.setByteSequenceContent(bytes);
            assertEquals(JadeMapping.canon(content), JadeMapping.canon(manager.extract(msg)), "case " + i);
            binaryBytes += bytes.length;
            slChars += sl.write(abs).length();
        }
        assertTrue(binaryBytes < slChars, binaryBytes + " bytes binary, " + slChars + " characters SL");
    }

    @Test
    void aFixedContentHasAFixedEncoding() throws Exception {
        byte[] bytes = binary.write(List.of(AbsCompound.positional("p", new AbsPrimitive(-1L), new AbsPrimitive("é"),
                new AbsAggregate("set", List.of(new AbsPrimitive(true))), AbsCompound.positional("p"))));
        assertArrayEquals(new byte[] {1, 1, 14, 0, 1, 'p', 4, 2, 1, 1, 2, (byte) 0xC3, (byte) 0xA9, 12, 1, 6, 14, 1, 0}, bytes);
    }

    @Test
    void theContentManagerCarriesItAsByteContent() throws Exception {
        ContentManager m = new ContentManager().register(new BinaryContentCodec()).register(ontology);
        AclMessage msg = new AclMessage(Performative.INFORM);
        Done done = new Done(new Action(new AID("a@P"), new BookShop.Sell(
                new BookShop.Book("T", 1, null, 1, 1, true, null, new byte[] {1}, null, null, null), null, null, null)));
        m.fill(msg, done);
        assertEquals("concord-binary", msg.getLanguage());
        assertTrue(msg.hasByteSequenceContent());
        assertEquals(JadeMapping.canon(done), JadeMapping.canon(m.extract(msg)));
    }

    @Test
    void corruptedBytesGiveOnlyTheCodecsOwnException() throws Exception {
        Random r = new Random(SEED);
        ContentGenerator g = new ContentGenerator(SEED);
        int refused = 0;
        for (int i = 0; i < INPUTS; i++) {
            byte[] bytes = binary.write(List.of(ontology.toAbs(g.contentElement())));
            int edits = 1 + r.nextInt(3);
            for (int k = 0; k < edits; k++) {
                int at = r.nextInt(bytes.length);
                if (r.nextInt(4) == 0) {
                    bytes = java.util.Arrays.copyOf(bytes, at);
                    if (bytes.length == 0) {
                        break;
                    }
                } else {
                    bytes[at] = (byte) r.nextInt(256);
                }
            }
            try {
                for (AbsObject abs : binary.read(bytes)) {
                    try {
                        ontology.fromAbs(abs);
                    } catch (ContentException e) {
                        // well-formed but against the schema
                    }
                }
            } catch (ContentException e) {
                refused++;
            } catch (Throwable t) {
                fail("unexpected " + t + " for input " + java.util.HexFormat.of().formatHex(bytes), t);
            }
            if (i > 2_000 && i % 2 == 0) {
                g = new ContentGenerator(SEED + i);
            }
        }
        assertTrue(refused > 0, "no corrupted input was refused");
    }

    @Test
    void nestingAndSizeAreBounded() {
        byte[] deep = new byte[10_000];
        deep[0] = 1;
        deep[1] = 1;
        for (int i = 2; i < deep.length - 1; i += 2) {
            deep[i] = BinaryContentCodec.SEQUENCE;
            deep[i + 1] = 1;
        }
        assertTrue(assertThrows(ContentException.class, () -> binary.read(deep)).getMessage().contains("nesting deeper"));
        assertTrue(assertThrows(ContentException.class, () -> new BinaryContentCodec(8, 10).read(new byte[11]))
                .getMessage().contains("over the limit of 10"));
        byte[] hugeCount = {1, 1, BinaryContentCodec.STRING, (byte) 0xFF, (byte) 0xFF, (byte) 0xFF, (byte) 0x7F};
        assertTrue(assertThrows(ContentException.class, () -> binary.read(hugeCount)).getMessage().contains("runs past the end"));
    }
}
