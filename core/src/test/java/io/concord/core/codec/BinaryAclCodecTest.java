package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.HexFormat;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class BinaryAclCodecTest {
    private final BinaryAclCodec codec = BinaryAclCodec.INSTANCE;

    @Test
    void roundTripsGeneratedMessagesExactly() throws Exception {
        for (long seed = 0; seed < 5_000; seed++) {
            AclMessage m = new AclGenerator(seed).message();
            AclMessage back = codec.decode(codec.encode(m));
            assertTrue(m.sameAs(back), "seed " + seed + ": " + m + "\nbecame\n" + back);
            assertEquals(m.hasByteSequenceContent(), back.hasByteSequenceContent(), "seed " + seed);
        }
    }

    /** The test vector of docs/wire-format.md. */
    @Test
    void encodesTheDocumentedTestVector() throws Exception {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.setSender(new AID("a@p", "udp://127.0.0.1:7001"));
        m.addReceiver(new AID("b@p"));
        m.setContent("hi");
        m.setConversationId("c1");
        String hex = HexFormat.of().formatHex(codec.encode(m));
        assertEquals("a107" + "8b04" + "03614070" + "01" + "14" + "7564703a2f2f3132372e302e302e313a37303031" + "00" + "00"
                + "01" + "03624070" + "00" + "00" + "00" + "026869" + "026331", hex);
        assertTrue(m.sameAs(codec.decode(HexFormat.of().parseHex(hex))));
    }

    @Test
    void rejectsEveryTruncationWithAParseError() {
        AclMessage m = new AclGenerator(7).message().setContent("some content").setConversationId("conv");
        byte[] full = codec.encode(m);
        for (int len = 0; len < full.length; len++) {
            int l = len;
            assertThrows(AclParseException.class, () -> codec.decode(full, 0, l), "truncated to " + len);
        }
    }

    @Test
    void rejectsTrailingBytes() {
        byte[] full = codec.encode(new AclMessage(Performative.INFORM));
        byte[] longer = java.util.Arrays.copyOf(full, full.length + 1);
        AclParseException e = assertThrows(AclParseException.class, () -> codec.decode(longer));
        assertEquals(full.length, e.offset());
    }

    @Test
    void rejectsAWrongVersionAndPerformative() {
        AclParseException v = assertThrows(AclParseException.class, () -> codec.decode(new byte[]{0x00, 0x07, 0x00}));
        assertEquals(0, v.offset());
        AclParseException p = assertThrows(AclParseException.class, () -> codec.decode(new byte[]{(byte) 0xA1, 22, 0x00}));
        assertEquals(1, p.offset());
    }

    @Test
    void refusesLengthsLongerThanWhatIsLeftWithoutAllocating() {
        // sender present, name length 2^31: must fail on the length, not try to allocate.
        byte[] evil = {(byte) 0xA1, 7, 0x01, (byte) 0xff, (byte) 0xff, (byte) 0xff, (byte) 0xff, 0x07};
        AclParseException e = assertThrows(AclParseException.class, () -> codec.decode(evil));
        assertEquals(3, e.offset());
    }

    @Test
    void rejectsBothKindsOfContentAtOnce() {
        byte[] both = {(byte) 0xA1, 7, 0x18};
        assertThrows(AclParseException.class, () -> codec.decode(both));
    }

    @Test
    void checksTheByteRange() {
        assertThrows(AclParseException.class, () -> codec.decode(new byte[4], 3, 5));
    }

    @Test
    void receiversAreCheckedWhenDecodedEvenIfBuiltLater() throws Exception {
        AclMessage m = new AclMessage(Performative.INFORM);
        m.addReceiver(new AID("b@p", List.of("udp://h:1"), List.of(), java.util.Map.of("role", "seller")));
        byte[] good = codec.encode(m);
        AclMessage back = codec.decode(good);
        assertEquals("seller", back.getReceivers().get(0).userDefined().get("role"));
        // Damage the slot name inside the receiver: decoding must fail now, not when the list is read.
        byte[] bad = good.clone();
        int at = new String(bad, java.nio.charset.StandardCharsets.ISO_8859_1).indexOf("role");
        bad[at] = '9';
        assertThrows(AclParseException.class, () -> codec.decode(bad));
    }

    @Test
    void aDecodedReceiverListIsLiveAndModifiable() throws Exception {
        AclMessage m = new AclMessage(Performative.INFORM).addReceiver(new AID("b@p")).addReceiver(new AID("c@p"));
        AclMessage back = codec.decode(codec.encode(m));
        back.addReceiver(new AID("d@p"));
        assertEquals(List.of(new AID("b@p"), new AID("c@p"), new AID("d@p")), back.getReceivers());
        assertTrue(back.copy().sameAs(back));
    }
}
