package io.concord.jade;

import org.xml.sax.ContentHandler;
import org.xml.sax.DTDHandler;
import org.xml.sax.EntityResolver;
import org.xml.sax.ErrorHandler;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;
import org.xml.sax.SAXNotRecognizedException;
import org.xml.sax.SAXNotSupportedException;
import org.xml.sax.XMLReader;

import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;
import java.io.IOException;

/**
 * The fix JADE 4.3 needs to receive HTTP messages on Java 9 and later: its HTTP MTP instantiates the
 * JDK's internal SAX parser class by reflection, which the module system forbids, and then drops
 * every inbound message. Give JADE this public reader instead, with the profile parameter
 * {@code jade_mtp_http_parser=io.concord.jade.JadeSaxParser} (on the command line:
 * {@code -jade_mtp_http_parser io.concord.jade.JadeSaxParser}); no JVM flag is needed. It wraps the
 * JDK's parser with namespace awareness on (without it JADE answers 200 and drops the message).
 */
public final class JadeSaxParser implements XMLReader {
    private final XMLReader delegate;

    public JadeSaxParser() {
        try {
            SAXParserFactory f = SAXParserFactory.newInstance();
            f.setNamespaceAware(true);
            // What arrives over HTTP is anyone's: no DOCTYPE, so no external or expanding entities
            // (a FIPA envelope has none).
            f.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            f.setFeature("http://xml.org/sax/features/external-general-entities", false);
            f.setFeature("http://xml.org/sax/features/external-parameter-entities", false);
            f.setFeature(javax.xml.XMLConstants.FEATURE_SECURE_PROCESSING, true);
            delegate = f.newSAXParser().getXMLReader();
        } catch (ParserConfigurationException | SAXException e) {
            throw new IllegalStateException("this JVM has no SAX parser: " + e.getMessage(), e);
        }
    }

    @Override
    public boolean getFeature(String name) throws SAXNotRecognizedException, SAXNotSupportedException {
        return delegate.getFeature(name);
    }

    @Override
    public void setFeature(String name, boolean value) throws SAXNotRecognizedException, SAXNotSupportedException {
        delegate.setFeature(name, value);
    }

    @Override
    public Object getProperty(String name) throws SAXNotRecognizedException, SAXNotSupportedException {
        return delegate.getProperty(name);
    }

    @Override
    public void setProperty(String name, Object value) throws SAXNotRecognizedException, SAXNotSupportedException {
        delegate.setProperty(name, value);
    }

    @Override
    public void setEntityResolver(EntityResolver resolver) {
        delegate.setEntityResolver(resolver);
    }

    @Override
    public EntityResolver getEntityResolver() {
        return delegate.getEntityResolver();
    }

    @Override
    public void setDTDHandler(DTDHandler handler) {
        delegate.setDTDHandler(handler);
    }

    @Override
    public DTDHandler getDTDHandler() {
        return delegate.getDTDHandler();
    }

    @Override
    public void setContentHandler(ContentHandler handler) {
        delegate.setContentHandler(handler);
    }

    @Override
    public ContentHandler getContentHandler() {
        return delegate.getContentHandler();
    }

    @Override
    public void setErrorHandler(ErrorHandler handler) {
        delegate.setErrorHandler(handler);
    }

    @Override
    public ErrorHandler getErrorHandler() {
        return delegate.getErrorHandler();
    }

    @Override
    public void parse(InputSource input) throws IOException, SAXException {
        delegate.parse(input);
    }

    @Override
    public void parse(String systemId) throws IOException, SAXException {
        delegate.parse(systemId);
    }
}
