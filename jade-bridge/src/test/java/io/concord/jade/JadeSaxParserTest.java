package io.concord.jade;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.xml.sax.InputSource;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The SAX parser given to JADE reads envelopes, and no entity that reaches outside the message. */
class JadeSaxParserTest {

    private static String text(String xml) throws Exception {
        StringBuilder out = new StringBuilder();
        JadeSaxParser p = new JadeSaxParser();
        p.setContentHandler(new DefaultHandler() {
            @Override
            public void characters(char[] ch, int start, int length) {
                out.append(ch, start, length);
            }
        });
        p.parse(new InputSource(new StringReader(xml)));
        return out.toString();
    }

    @Test
    void anEnvelopeIsRead() throws Exception {
        assertEquals("7", text("<?xml version=\"1.0\"?><envelope><params index=\"1\"><payload-length>7</payload-length></params></envelope>"));
    }

    @Test
    void anExternalEntityIsRefusedAndNothingIsRead(@TempDir Path dir) throws Exception {
        Path secret = dir.resolve("secret.txt");
        Files.writeString(secret, "the platform key");
        String xml = "<?xml version=\"1.0\"?><!DOCTYPE envelope [<!ENTITY s SYSTEM \"" + secret.toUri() + "\">]><envelope>&s;</envelope>";
        SAXParseException e = assertThrows(SAXParseException.class, () -> text(xml));
        assertTrue(e.getMessage().contains("DOCTYPE"), e.getMessage());
        String billion = "<?xml version=\"1.0\"?><!DOCTYPE e [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;\">]><e>&b;</e>";
        assertThrows(SAXParseException.class, () -> text(billion));
        assertFalse(e.getMessage().contains("the platform key"));
    }
}
