package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import io.concord.core.time.ManualClock;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneId;
import java.util.List;
import java.util.Map;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

class StringAclCodecTest {
    private final ManualClock clock = new ManualClock();
    private final StringAclCodec codec = new StringAclCodec(clock, StandardCharsets.UTF_8);

    private AclMessage read(String s) throws AclParseException {
        return codec.decode(s);
    }

    /** Messages written the way JADE 4.3 writes them (JADE-INTEROP.md, section 2 and 1). */
    @Nested
    class JadeCorpus {
        @Test
        void readsJadesOwnOutputWithEverySlot() throws Exception {
            String jade = """
                    (QUERY-REF
                     :sender  ( agent-identifier :name alice@plat1  :addresses (sequence http://host1:7778/acc ))
                     :receiver  (set ( agent-identifier :name bob@plat2  :addresses (sequence http://host2:7778/acc http://host2b:7778/acc )) )
                     :reply-to  (set
                    ( agent-identifier :name alice@plat1  :addresses (sequence http://host1:7778/acc )) )
                     :content  "say \\"hi\\" \\ there"
                     :reply-with  r1  :in-reply-to  i1  :encoding  utf8  :language  fipa-sl0  :ontology  onto  :reply-by  20231114T221320123Z
                     :protocol  fipa-query
                     :conversation-id  c1 :X-foo "bar baz" :X-custom v )""";
            AclMessage m = read(jade);
            assertEquals(Performative.QUERY_REF, m.getPerformative());
            assertEquals("alice@plat1", m.getSender().name());
            assertEquals(List.of("http://host1:7778/acc"), m.getSender().addresses());
            assertEquals(1, m.getReceivers().size());
            assertEquals(List.of("http://host2:7778/acc", "http://host2b:7778/acc"), m.getReceivers().get(0).addresses());
            assertEquals("alice@plat1", m.getReplyTo().get(0).name());
            assertEquals("say \"hi\" \\ there", m.getContent());
            assertEquals("r1", m.getReplyWith());
            assertEquals("i1", m.getInReplyTo());
            assertEquals("utf8", m.getEncoding());
            assertEquals("fipa-sl0", m.getLanguage());
            assertEquals("onto", m.getOntology());
            assertEquals(Instant.parse("2023-11-14T22:13:20.123Z").toEpochMilli(), m.getReplyByEpochMs());
            assertEquals("fipa-query", m.getProtocol());
            assertEquals("c1", m.getConversationId());
            assertEquals(Map.of("foo", "bar baz", "custom", "v"), m.getUserDefinedParameters());
        }

        /** JADE escapes only quotes and reads the longest string its lexer can match. */
        @Test
        void readsContentEndingInABackslashAsJadeWritesIt() throws Exception {
            assertEquals("ends with backslash\\", read("(INFORM\n :content  \"ends with backslash\\\" \n)").getContent());
            assertEquals("\\", read("(INFORM :content \"\\\" :protocol fipa-request)").getContent());
            assertEquals("quote\" end\\", read("(INFORM :content \"quote\\\" end\\\" :language fipa-sl)").getContent());
            assertEquals("a\\\"b", read("(INFORM :content \"a\\\\\"b\")").getContent(), "JADE's writing of a\\\"b");
            assertEquals("a\\ b", read("(INFORM :content \"a\\ b\")").getContent());
        }

        /**
         * Where a quoted slot follows, JADE's lexer runs on to that quote and JADE fails on its own
         * message; this reader then tries the string ending at the escaped-looking quote.
         */
        @Test
        void readsContentEndingInABackslashEvenWhereJadeItselfCannot() throws Exception {
            AclMessage m = read("(INFORM :content \"x\\\" :ontology \"-x\" :conversation-id \"c 1\")");
            assertEquals("x\\", m.getContent());
            assertEquals("-x", m.getOntology());
            assertEquals("c 1", m.getConversationId());
            AclMessage two = read("(INFORM :content \"a\\\" :language \"b\\\" :ontology \"o\")");
            assertEquals("a\\", two.getContent());
            assertEquals("b\\", two.getLanguage());
        }

        @Test
        void triesABoundedNumberOfReadingsOfAmbiguousStrings() {
            String many = "(INFORM" + " :X-a \"v\\\" :X-b \"w\\\"".repeat(5_000) + " :bogus)";
            AclParseException e = assertThrows(AclParseException.class, () -> read(many));
            assertTrue(e.getMessage().contains("parameter"), e.getMessage());
        }

        /** JADE reads and writes dates with GregorianCalendar: Julian before 15 October 1582. */
        @Test
        void readsAndWritesDatesBefore1582InTheJulianCalendarAsJadeDoes() throws Exception {
            // The instants JADE 4.3 gives these dates (GregorianCalendar, UTC).
            String[][] jade = {{"15821015T000000000Z", "-12219292800000"}, {"15821004T000000000Z", "-12219379200000"},
                    {"00010101T000000000Z", "-62135769600000"}, {"15000229T000000000Z", "-14825894400000"},
                    {"10000101T120000000Z", "-30609748800000"}};
            for (String[] j : jade) {
                String text = j[0];
                long[] d = {0, Long.parseLong(j[1])};
                assertEquals(d[1], read("(INFORM :reply-by " + text + ")").getReplyByEpochMs(), text);
                assertEquals(text, FipaDates.format(d[1]), "writes " + d[1] + " as JADE does");
            }
            assertThrows(AclParseException.class, () -> read("(INFORM :reply-by 15821010T000000000Z)"),
                    "10 October 1582 never was");
            assertThrows(AclParseException.class, () -> read("(INFORM :reply-by 00000101T000000000Z)"), "no year 0");
            assertThrows(IllegalArgumentException.class, () -> FipaDates.format(-62135769600001L), "before the year 1");
            assertThrows(IllegalArgumentException.class, () -> FipaDates.format(253402300800000L), "after 9999");
            AclMessage far = new AclMessage(Performative.INFORM).setReplyByEpochMs(253402300800000L);
            assertThrows(IllegalArgumentException.class, () -> codec.encodeForJade(far), "JADE cannot read the year 10000");
            assertTrue(far.toString().contains(":reply-by"), "toString and Concord's own hops never throw");
        }

        @Test
        void readsTheMinimalMessageJadeAccepts() throws Exception {
            AclMessage m = read("(request :sender (agent-identifier :name a@ext :addresses (sequence "
                    + "http://10.0.0.2:7778/acc)) :receiver (set (agent-identifier :name echo@P)) :content \"ping\")");
            assertEquals(Performative.REQUEST, m.getPerformative());
            assertEquals("echo@P", m.getReceivers().get(0).name());
            assertEquals("ping", m.getContent());
        }

        @Test
        void readsJadesAmsFailureForAnUnknownReceiver() throws Exception {
            AclMessage m = read("(FAILURE\n :sender  ( agent-identifier :name ams@P  :addresses (sequence http://h:7778/acc ))\n"
                    + " :receiver  (set ( agent-identifier :name a@ext ) )\n"
                    + " :content  \"( (action ( agent-identifier :name a@ext ) (ACLMessage) ) (MTS-error ( agent-identifier"
                    + " :name nobody@P ) (internal-error \\\"Agent not found: getContainerID() failed to find agent nobody@P\\\")) )\" \n"
                    + " :language  fipa-sl  \n :conversation-id  orig )");
            assertEquals(Performative.FAILURE, m.getPerformative());
            assertTrue(m.getContent().contains("(internal-error \"Agent not found: getContainerID() failed"));
            assertEquals("orig", m.getConversationId());
        }

        @Test
        void readsADfSearchRequestAndItsInform() throws Exception {
            AclMessage req = read("(REQUEST :sender (agent-identifier :name j@J) :receiver (set (agent-identifier :name df@P))"
                    + " :language fipa-sl0 :ontology FIPA-Agent-Management :protocol fipa-request :content "
                    + "\"((action (agent-identifier :name df@P) (search (df-agent-description :services (set "
                    + "(service-description :type echo-service))) (search-constraints :max-results -1))))\")");
            assertEquals("FIPA-Agent-Management", req.getOntology());
            assertTrue(req.getContent().startsWith("((action (agent-identifier :name df@P) (search"));
            AclMessage inform = read("(INFORM :sender (agent-identifier :name df@P) :receiver (set (agent-identifier :name j@J))"
                    + " :content \"((result (action (agent-identifier :name df@P) (search)) (sequence (df-agent-description"
                    + " :name (agent-identifier :name echo@P) :services (set (service-description :type echo-service))))))\""
                    + " :language fipa-sl0 :ontology FIPA-Agent-Management :protocol fipa-request)");
            assertTrue(inform.getContent().contains(":type echo-service"));
        }

        @Test
        void readsAByteStringContentOfExactlyItsLength() throws Exception {
            AclMessage m = read("(INFORM :content #5\"hello :language x)");
            assertTrue(m.hasByteSequenceContent());
            assertArrayEquals("hello".getBytes(StandardCharsets.US_ASCII), m.getByteSequenceContent());
            assertEquals("x", m.getLanguage());
        }

        @Test
        void readsJadesBase64ByteContent() throws Exception {
            AclMessage m = read("(INFORM :content \"AAEC/w==\" :X-JADE-Encoding Base64 )");
            assertArrayEquals(new byte[]{0, 1, 2, (byte) 0xff}, m.getByteSequenceContent());
            assertTrue(m.getUserDefinedParameters().isEmpty(), "the encoding marker is not a user parameter");
        }

        @Test
        void keepsNestedExpressionsInSlotsAsTheirText() throws Exception {
            AclMessage m = read("(INFORM :reply-with (foo (bar \"x)\")) :content (a (b c)))");
            assertEquals("(foo (bar \"x)\"))", m.getReplyWith());
            assertEquals("(a (b c))", m.getContent());
        }

        @Test
        void acceptsAnyCaseAndWhitespace() throws Exception {
            AclMessage m = read("\n\t( inform\t:SENDER\n(Agent-Identifier :NAME a@b)   :Content\t\"x\"\r\n)\n");
            assertEquals(Performative.INFORM, m.getPerformative());
            assertEquals("a@b", m.getSender().name());
            assertEquals("x", m.getContent());
        }

        @Test
        void readsBareNumbersAsJadeWritesThem() throws Exception {
            AclMessage m = read("(INFORM :conversation-id 12345 :X-count 42 :content 7)");
            assertEquals("12345", m.getConversationId());
            assertEquals("42", m.getUserDefinedParameter("count"));
            assertEquals("7", m.getContent());
        }

        @Test
        void readsAidsWithResolversQuotedNamesAndSlots() throws Exception {
            AclMessage m = read("(INFORM :sender (agent-identifier :name \"odd name@p\" :addresses (sequence a b)"
                    + " :resolvers (sequence (agent-identifier :name r@p)) :X-role buyer))");
            AID s = m.getSender();
            assertEquals("odd name@p", s.name());
            assertEquals("r@p", s.resolvers().get(0).name());
            assertEquals(Map.of("role", "buyer"), s.userDefined());
        }

        @Test
        void keepsTheLastValueOfARepeatedSlot() throws Exception {
            assertEquals("b", read("(INFORM :language a :language b)").getLanguage());
        }

        @Test
        void readsReplyByWithoutZAsLocalTime() throws Exception {
            AclMessage m = read("(INFORM :reply-by 20231114T221320123)");
            long expected = LocalDateTime.of(2023, 11, 14, 22, 13, 20, 123_000_000)
                    .atZone(ZoneId.systemDefault()).toInstant().toEpochMilli();
            assertEquals(expected, m.getReplyByEpochMs());
        }

        @Test
        void readsARelativeReplyByFromThePlatformClock() throws Exception {
            AclMessage m = read("(INFORM :reply-by +00000000T000130500Z)");
            assertEquals(clock.epochMillis() + 90_500, m.getReplyByEpochMs());
        }
    }

    @Nested
    class Writing {
        @Test
        void writesJadesLayout() {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.setSender(new AID("alice@p", "udp://127.0.0.1:7001"));
            m.addReceiver(new AID("bob@p"));
            m.setContent("hello");
            m.setProtocol("fipa-request");
            m.setConversationId("c1");
            String s = codec.encodeToString(m);
            assertEquals("(INFORM\n :sender  ( agent-identifier :name alice@p  :addresses (sequence udp://127.0.0.1:7001 ))\n"
                    + " :receiver  (set ( agent-identifier :name bob@p ) )\n :content  \"hello\"\n"
                    + "\n :protocol  fipa-request\n :conversation-id  c1 )", s);
        }

        @Test
        void quotesEveryValueThatIsNotAPlainAsciiWord() {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.setConversationId("123");
            m.setOntology("my onto");
            m.setLanguage("-abc");
            m.setReplyWith("café");
            m.setInReplyTo("a(b");
            String s = codec.encodeToString(m);
            assertTrue(s.contains(":conversation-id  \"123\""), s);
            assertTrue(s.contains(":ontology  \"my onto\""), s);
            assertTrue(s.contains(":language  \"-abc\""), s);
            assertTrue(s.contains(":reply-with  \"café\""), s);
            assertTrue(s.contains(":in-reply-to  \"a(b\""), s);
        }

        @Test
        void escapesOnlyTheQuoteInContentAndKeepsItsWhitespace() {
            AclMessage m = new AclMessage(Performative.INFORM).setContent("  say \"hi\" \\ there ");
            assertTrue(codec.encodeToString(m).contains(":content  \"  say \\\"hi\\\" \\ there \""));
        }

        @Test
        void writesContentEndingInABackslashLastInTheMessageAsJadeDoes() throws Exception {
            AclMessage m = new AclMessage(Performative.INFORM).setContent("dir\\").setOntology("my onto")
                    .setConversationId("c 1");
            String s = codec.encodeToString(m);
            assertTrue(s.endsWith(" :content  \"dir\\\" )"), "no quote may follow it, or JADE's lexer reads on: " + s);
            AclMessage back = codec.decode(s);
            assertEquals("dir\\", back.getContent());
            assertEquals("my onto", back.getOntology());
            assertEquals("c 1", back.getConversationId());
        }

        @Test
        void writesASecondValueEndingInABackslashAsAByteStringAndRefusesItForJadeIfNotAscii() throws Exception {
            AclMessage m = new AclMessage(Performative.INFORM).setContent("dir\\").setOntology("my onto\\");
            String s = codec.encodeForJade(m);
            assertTrue(s.contains(":ontology  #8\"my onto\\"), s);
            assertEquals("my onto\\", codec.decode(s).getOntology());
            m.setOntology("café \\");
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> codec.encodeForJade(m));
            assertTrue(e.getMessage().contains("ontology"), e.getMessage());
            assertEquals("café \\", codec.decode(codec.encodeToString(m)).getOntology(), "Concord's own hops carry it");
        }

        @Test
        void writesAProtocolThatIsNotAWordOnlyForConcordAndRefusesItForJade() throws Exception {
            AclMessage m = new AclMessage(Performative.REQUEST).setProtocol("my protocol");
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> codec.encodeForJade(m));
            assertTrue(e.getMessage().contains("protocol 'my protocol'"), e.getMessage());
            assertEquals("my protocol", codec.decode(codec.encodeToString(m)).getProtocol());
            m.setProtocol("fipa-request");
            assertTrue(codec.encodeForJade(m).contains(":protocol  fipa-request"));
        }

        @Test
        void refusesForJadeAnAddressJadeCannotRead() {
            AclMessage m = new AclMessage(Performative.INFORM).setSender(new AID("a@p", "http://host/a b"));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> codec.encodeForJade(m));
            assertTrue(e.getMessage().contains("address 'http://host/a b'"), e.getMessage());
            m.setSender(new AID("a@p", "1http://host/x"));
            assertTrue(codec.encodeForJade(m).contains("(sequence \"1http://host/x\" )"), "quoted, which JADE reads");
        }

        @Test
        void writesReplyByInUtcAndUserParametersWithX() {
            AclMessage m = new AclMessage(Performative.INFORM);
            m.setReplyByEpochMs(Instant.parse("2023-11-14T22:13:20.123Z").toEpochMilli());
            m.addUserDefinedParameter("X-foo", "bar baz");
            String s = codec.encodeToString(m);
            assertTrue(s.contains(":reply-by  20231114T221320123Z"), s);
            assertTrue(s.contains(":X-foo \"bar baz\""), s);
        }

        @Test
        void writesByteContentAsJadeDoesWithBase64() throws Exception {
            AclMessage m = new AclMessage(Performative.INFORM).setByteSequenceContent(new byte[]{0, 1, 2, (byte) 0xff});
            String s = codec.encodeToString(m);
            assertTrue(s.contains(":content  \"AAEC/w==\""), s);
            assertTrue(s.contains(":X-JADE-Encoding Base64"), s);
            assertArrayEquals(new byte[]{0, 1, 2, (byte) 0xff}, codec.decode(s).getByteSequenceContent());
        }
    }

    @Nested
    class Malformed {
        @Test
        void namesTheOffsetAndWhatWasExpectedForAnUnknownParameter() {
            AclParseException e = assertThrows(AclParseException.class, () -> read("(INFORM :bogus 1)"));
            assertEquals(8, e.offset());
            assertTrue(e.expected().contains("FIPA message parameter"), e.expected());
            assertTrue(e.found().contains(":bogus"), e.found());
        }

        @Test
        void rejectsAnUnknownPerformative() {
            AclParseException e = assertThrows(AclParseException.class, () -> read("(SHOUT :content \"x\")"));
            assertEquals(1, e.offset());
            assertTrue(e.expected().contains("performative"));
        }

        @Test
        void rejectsReceiversNotWrittenAsASet() {
            AclParseException e = assertThrows(AclParseException.class,
                    () -> read("(INFORM :receiver (agent-identifier :name a@b))"));
            assertEquals(19, e.offset());
        }

        @Test
        void rejectsAnAidWithoutAName() {
            assertThrows(AclParseException.class, () -> read("(INFORM :sender (agent-identifier :addresses (sequence a)))"));
        }

        @Test
        void rejectsABadDate() {
            AclParseException e = assertThrows(AclParseException.class, () -> read("(INFORM :reply-by 20231399T221320123Z)"));
            assertTrue(e.expected().contains("calendar"), e.getMessage());
        }

        @Test
        void rejectsTrailingGarbage() {
            AclParseException e = assertThrows(AclParseException.class, () -> read("(INFORM) (INFORM)"));
            assertEquals(9, e.offset());
        }

        @ParameterizedTest
        @ValueSource(strings = {"", "   ", "(", ")", "(INFORM", "(INFORM :content", "(INFORM :content \"abc",
                "(INFORM :content #10\"abc)", "(INFORM :content #99999999999\"a)", "(INFORM :sender (",
                "(INFORM :sender (agent-identifier :name", "(INFORM :X- 1)", "(INFORM :receiver (set (agent-identifier",
                "(INFORM :content ((((((", "INFORM", "(INFORM :reply-by)", "(INFORM :reply-by -20231114T221320123Z)",
                "(INFORM :sender (agent-identifier :name a :X-bad\" 1))", "(INFORM :content \u0000)"})
        void rejectsTruncatedAndBrokenInputWithAParseErrorOnly(String input) {
            AclParseException e = assertThrows(AclParseException.class, () -> read(input));
            assertTrue(e.offset() >= 0 && e.offset() <= input.length(), "offset within the input: " + e.offset());
        }

        @Test
        void survivesDeepNestingWithoutOverflowingTheStack() {
            String deep = "(INFORM :content " + "(".repeat(200_000) + ")";
            AclParseException e = assertThrows(AclParseException.class, () -> read(deep));
            assertTrue(e.expected().contains("nested"));
            String deepAid = "(INFORM :sender " + "(agent-identifier :name a :resolvers (sequence ".repeat(50) + ")";
            assertThrows(AclParseException.class, () -> read(deepAid));
        }

        @Test
        void decodesNoPartialMessage() throws Exception {
            AclMessage full = read("(INFORM :content \"x\" :language l)");
            assertEquals("l", full.getLanguage());
            assertThrows(AclParseException.class, () -> read("(INFORM :content \"x\" :language l :bogus 2)"));
        }
    }

    @Test
    void roundTripsGeneratedMessages() throws Exception {
        for (long seed = 0; seed < 2_000; seed++) {
            AclMessage m = new AclGenerator(seed).message();
            String text = codec.encodeToString(m);
            AclMessage back = codec.decode(text);
            assertTrue(m.sameAs(back), "seed " + seed + " changed in a round trip:\n" + text + "\n" + back);
            assertEquals(text, codec.encodeToString(back), "seed " + seed + ": writing is stable");
        }
    }

    @Test
    void leavesAbsentSlotsAbsent() throws Exception {
        AclMessage m = read("(CFP)");
        assertNull(m.getSender());
        assertNull(m.getContent());
        assertTrue(m.getReceivers().isEmpty());
    }
}
