package io.concord.jade;

import io.concord.core.acl.AID;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The HTTP MTP's wire pieces on their own: JADE's request as it sends it, the envelope, SL0. */
class WireTest {
    /** The request JADE 4.3 sends (JADE-INTEROP.md), with a message for bob. */
    static final String JADE_BODY = "This is not part of the MIME multipart encoded message.\r\n"
            + "--7b446481f5ae2c17c233efb80dd6246\r\nContent-Type: application/xml\r\n\r\n"
            + "<?xml version=\"1.0\"?>\n<envelope><params index=\"1\"><to><agent-identifier><name>bob@foreignplat</name>"
            + "<addresses><url>http://127.0.0.1:7779/acc</url></addresses></agent-identifier></to><from><agent-identifier>"
            + "<name>echo@TestPlat</name><addresses><url>http://127.0.0.1:7778/acc</url></addresses></agent-identifier></from>"
            + "<acl-representation>fipa.acl.rep.string.std</acl-representation><payload-length>120</payload-length>"
            + "<date>20261121Z080444961</date><intended-receiver><agent-identifier><name>bob@foreignplat</name><addresses>"
            + "<url>http://127.0.0.1:7779/acc</url></addresses></agent-identifier></intended-receiver></params></envelope>\r\n"
            + "--7b446481f5ae2c17c233efb80dd6246\r\nContent-Type: application/text\r\n\r\n"
            + "(REQUEST\n :sender  ( agent-identifier :name echo@TestPlat  :addresses (sequence http://127.0.0.1:7778/acc ))\n"
            + " :receiver  (set ( agent-identifier :name bob@foreignplat ) )\n :content  \"ping\" )\r\n"
            + "--7b446481f5ae2c17c233efb80dd6246--\r\n";

    @Test
    void readsTheRequestJadeSends() {
        String boundary = MtpMultipart.boundaryOf("multipart/mixed ; boundary=\"7b446481f5ae2c17c233efb80dd6246\"");
        assertEquals("7b446481f5ae2c17c233efb80dd6246", boundary);
        HttpMtp.Inbound in = HttpMtp.parse(JADE_BODY, boundary);
        assertEquals(List.of(new AID("bob@foreignplat")), in.envelope().deliverTo());
        assertEquals(Performative.REQUEST, in.message().getPerformative());
        assertEquals("ping", in.message().getContent());
        assertEquals("echo@TestPlat", in.message().getSender().name());
        assertEquals(List.of("http://127.0.0.1:7778/acc"), in.message().getSender().addresses());
    }

    @Test
    void rejectsWhatItCannotUseAndSaysWhy() {
        assertEquals(null, MtpMultipart.boundaryOf("text/plain"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HttpMtp.parse("no boundary here", "b"))
                .getMessage().contains("boundary"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HttpMtp.parse(
                JADE_BODY.replace("fipa.acl.rep.string.std", "fipa.acl.rep.bitefficient.std"), "7b446481f5ae2c17c233efb80dd6246"))
                .getMessage().contains("only fipa.acl.rep.string.std"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> HttpMtp.parse(
                JADE_BODY.replace("<intended-receiver>", "<x>").replace("</intended-receiver>", "</x>")
                        .replace("<to>", "<y>").replace("</to>", "</y>"), "7b446481f5ae2c17c233efb80dd6246"))
                .getMessage().contains("names no receiver"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> FipaEnvelope.parse(
                "<!DOCTYPE x [<!ENTITY e SYSTEM \"file:///etc/passwd\">]><envelope>&e;</envelope>"))
                .getMessage().contains("not well-formed"));
    }

    @Test
    void aMessageOverHttpCannotComeFromAnAgentOfThisPlatform() {
        String boundary = "7b446481f5ae2c17c233efb80dd6246";
        HttpMtp.Inbound foreign = HttpMtp.parse(JADE_BODY, boundary);
        HttpMtp.checkForeignSender(foreign, "foreignplat");
        HttpMtp.Inbound posing = HttpMtp.parse(JADE_BODY.replace(":name echo@TestPlat", ":name boss@foreignplat"), boundary);
        assertEquals("boss@foreignplat", posing.message().getSender().name());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> HttpMtp.checkForeignSender(posing, "foreignplat"));
        assertTrue(e.getMessage().contains("is an agent of this platform"), e.getMessage());
    }

    @Test
    void aRestrictedBridgeReachesOnlyTheJadePlatformsItTrusts() {
        HttpMtp.Trust t = new HttpMtp.Trust(java.util.Set.of("10.200.0.2:1099/JADE"), java.util.Set.of("10.200.0.2"));
        assertEquals(null, t.refuseFrom("10.200.0.2"));
        assertTrue(t.refuseFrom("127.0.0.1").contains("not trusted"));
        assertEquals(null, t.refuseSender(new AID("buyer@10.200.0.2:1099/jade")));
        assertTrue(t.refuseSender(new AID("buyer@evil")).contains("not trusted"));
        HttpMtp mtp = new HttpMtp("127.0.0.1", 1).trust(t);
        assertTrue(mtp.reaches(new AID("seller@10.200.0.2:1099/JADE", "http://10.200.0.2:7778/acc")));
        assertTrue(!mtp.reaches(new AID("seller@10.200.0.2:1099/JADE", "http://10.200.0.66:7778/acc")), "another address");
        assertTrue(!mtp.reaches(new AID("seller@evil", "http://10.200.0.2:7778/acc")), "another platform");
        assertTrue(new HttpMtp("127.0.0.1", 1).reaches(new AID("seller@evil", "http://10.200.0.66:7778/acc")),
                "unrestricted, any HTTP address");
    }

    @Test
    void theEnvelopeItWritesReadsBack() {
        AID bob = new AID("bob@j", "http://h:1/acc");
        AID me = new AID("me@c&co", "http://h:2/acc");
        FipaEnvelope e = FipaEnvelope.forOne(bob, me, 42, io.concord.core.time.ManualClock.DEFAULT_EPOCH_MS);
        String xml = e.toXml();
        assertTrue(xml.contains("<intended-receiver>") && !xml.contains("\n<params") && xml.contains("me@c&amp;co"), xml);
        assertTrue(e.date().matches("\\d{8}Z\\d{9}"), e.date());
        FipaEnvelope back = FipaEnvelope.parse(xml);
        assertEquals(List.of(bob), back.intendedReceivers());
        assertEquals("me@c&co", back.from().name());
        assertEquals(42, back.payloadLength());
        assertEquals("UTF-8", back.payloadEncoding());
    }

    /** The DF/AMS front end reads with core's SL codec and FIPA agent-management ontology, strictly. */
    @Test
    void agentManagementContentIsReadStrictly() throws Exception {
        io.concord.core.content.SlCodec sl = new io.concord.core.content.SlCodec();
        io.concord.core.content.Ontology onto = io.concord.core.content.FipaAgentManagement.ontology();
        io.concord.core.content.Action a = (io.concord.core.content.Action) onto.fromAbs(sl.read(
                "((action (agent-identifier :name df@P) (search (df-agent-description :services (set "
                + "(service-description :type \"my type\"))) (search-constraints :max-results -1))))").get(0));
        assertEquals("df@P", a.actor().name());
        String back = sl.write(onto.toAbs(a));
        assertTrue(back.contains(":type \"my type\""), back);
        for (String bad : new String[]{"((action", "(a) b", "word", "(\"open", "(".repeat(100) + ")".repeat(100)}) {
            assertThrows(io.concord.core.content.ContentException.class, () -> onto.fromAbs(sl.read(bad).get(0)), bad);
        }
    }
}
